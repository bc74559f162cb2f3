#pragma once
/// \file distributed_grid.h
/// \brief The grid statistics of a job's whole input: each rank bins its share, cells go to the
/// rank owning their tile (MPI_Alltoallv), owners reduce, rank 0 gathers the reduced cells.

#include "metricmap/grid/grid_accumulator.h"

namespace metricmap::distributed {

/// \brief Collective. `local` holds this rank's share (world-aligned cells). Returns, on rank 0,
/// the accumulator of every rank's input (equal to a one-process build of all of it); on the
/// other ranks an empty accumulator of the same cell size.
/// \throws InputError when a received buffer is corrupt; CapacityError (see exchangeBuffers)
GridAccumulator reduceGrid(const GridAccumulator& local);

/// \brief Collective. Only the summary of the whole job (no cells) on rank 0, for
/// gridStatisticsOf: the same exchange and owner reduction, then a few numbers per rank instead
/// of the cells (counts summed, cell boxes min/max-ed). Other ranks get an empty summary.
GridSummary reduceGridSummary(const GridAccumulator& local);

}  // namespace metricmap::distributed
