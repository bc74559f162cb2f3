#include "metricmap/distributed/distributed_occupancy.h"

#include <stdexcept>
#include <string>

#include "metricmap/distributed/exchange.h"
#include "metricmap/exceptions.h"
#include "metricmap/occupancy/log_odds_transfer.h"

namespace metricmap::distributed {
namespace {

void mergeInto(LogOddsMap& map, const Bytes& bytes, const std::string& what) {
  const LogOddsMap part = deserializeLogOdds(bytes.data(), bytes.size(), what);
  try {
    map.merge(part);
  } catch (const std::invalid_argument& e) {
    throw InputError(what + ": " + e.what());
  }
}

}  // namespace

LogOddsMap reduceLogOdds(const LogOddsMap& local) {
  const int size = worldSize();
  const std::vector<Bytes> incoming =
      exchangeBuffers(serializeLogOddsByOwner(local, static_cast<unsigned>(size)));
  LogOddsMap owned(local.params());
  for (int k = 0; k < size; ++k)  // rank order = frame order
    mergeInto(owned, incoming[k], "voxels from rank " + std::to_string(k));
  const std::vector<Bytes> gathered = gatherBuffers(serializeLogOdds(owned));
  LogOddsMap all(local.params());
  for (std::size_t k = 0; k < gathered.size(); ++k)
    mergeInto(all, gathered[k], "merged voxels of rank " + std::to_string(k));
  return all;
}

}  // namespace metricmap::distributed
