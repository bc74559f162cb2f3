#include "metricmap/distributed/distributed_occupancy.h"

#include <string>

#include "metricmap/distributed/exchange.h"
#include "metricmap/occupancy/log_odds_transfer.h"

namespace metricmap::distributed {
LogOddsMap reduceLogOdds(const LogOddsMap& local) {
  const int size = worldSize();
  if (size == 1) return local;  // nothing to exchange
  const std::vector<Bytes> incoming =
      exchangeBuffers(serializeLogOddsByOwner(local, static_cast<unsigned>(size)));
  LogOddsMap owned(local.params());
  for (int k = 0; k < size; ++k)  // rank order = frame order
    mergeSerializedLogOdds(owned, incoming[k].data(), incoming[k].size(),
                           "voxels from rank " + std::to_string(k));
  // rank 0 keeps its own tiles as they are and adds the other owners' (disjoint) voxels
  const std::vector<Bytes> gathered =
      gatherBuffers(worldRank() == 0 ? Bytes() : serializeLogOdds(owned));
  if (worldRank() != 0) return LogOddsMap(local.params());
  for (std::size_t k = 1; k < gathered.size(); ++k)
    mergeSerializedLogOdds(owned, gathered[k].data(), gathered[k].size(),
                           "merged voxels of rank " + std::to_string(k));
  return owned;
}

}  // namespace metricmap::distributed
