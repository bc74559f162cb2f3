#pragma once
/// \file distributed_occupancy.h
/// \brief A probabilistic map of a job's whole input: each rank casts its share of the scans,
/// voxels go to the rank owning their tile (MPI_Alltoallv), owners merge the log-odds in rank
/// order, rank 0 gathers the merged voxels. See log_odds_transfer.h for what merging equals.

#include "metricmap/occupancy/log_odds_map.h"

namespace metricmap::distributed {

/// \brief Collective. Returns on rank 0 the merge of every rank's map; on the other ranks an
/// empty map with the same parameters.
/// \throws InputError when a received buffer is corrupt or the ranks' parameters differ
LogOddsMap reduceLogOdds(LogOddsMap local);

}  // namespace metricmap::distributed
