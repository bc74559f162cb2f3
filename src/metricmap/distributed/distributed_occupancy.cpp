#include "metricmap/distributed/distributed_occupancy.h"

#include <string>

#include "metricmap/distributed/exchange.h"
#include "metricmap/occupancy/log_odds_transfer.h"

namespace metricmap::distributed {
LogOddsMap reduceLogOdds(LogOddsMap local) {
  const int size = worldSize();
  if (size == 1) return local;  // nothing to exchange
  const auto rank = static_cast<unsigned>(worldRank()), parts = static_cast<unsigned>(size);
  // This rank's own tiles stay in memory; the other owners' go out.
  const Received incoming = exchangeBuffers(serializeLogOddsByOwner(local, parts, rank));
  LogOddsMap owned(local.params());
  for (unsigned k = 0; k < parts; ++k) {  // rank order = frame order
    if (k == rank) {
      mergeOwnedBlocks(owned, local, rank, parts);
    } else {
      mergeSerializedLogOdds(owned, incoming.data(k), incoming.size[k],
                             "voxels from rank " + std::to_string(k));
    }
  }
  // rank 0 keeps its own tiles as they are and adds the other owners' (disjoint) voxels
  const Received gathered = gatherBuffers(rank == 0 ? Bytes() : serializeLogOdds(owned));
  if (rank != 0) return LogOddsMap(local.params());
  for (std::size_t k = 1; k < gathered.ranks(); ++k)
    mergeSerializedLogOdds(owned, gathered.data(k), gathered.size[k],
                           "merged voxels of rank " + std::to_string(k));
  return owned;
}

}  // namespace metricmap::distributed
