#include "metricmap/distributed/distributed_grid.h"

#include <string>

#include "metricmap/distributed/exchange.h"

namespace metricmap::distributed {

GridAccumulator reduceGrid(const GridAccumulator& local) {
  const int size = worldSize();
  if (size == 1) return local;  // nothing to exchange
  // 1. each rank sends every owner the cells of its tiles
  const std::vector<Bytes> incoming =
      exchangeBuffers(local.serializeByOwner(static_cast<unsigned>(size)));
  // 2. each owner reduces its tiles, in source-rank order (deterministic sums)
  GridAccumulator owned(local.cellSize());
  for (int k = 0; k < size; ++k) {
    owned.merge(GridAccumulator::deserialize(incoming[k].data(), incoming[k].size(),
                                             "grid cells from rank " + std::to_string(k)));
  }
  // 3. rank 0 gathers the owners' disjoint cells
  const std::vector<Bytes> gathered = gatherBuffers(owned.serialize());
  GridAccumulator all(local.cellSize());
  for (std::size_t k = 0; k < gathered.size(); ++k) {
    all.merge(GridAccumulator::deserialize(gathered[k].data(), gathered[k].size(),
                                           "reduced grid cells of rank " + std::to_string(k)));
  }
  return all;
}

}  // namespace metricmap::distributed
