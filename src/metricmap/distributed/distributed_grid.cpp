#include "metricmap/distributed/distributed_grid.h"

#include <limits>
#include <string>

#include "metricmap/distributed/exchange.h"

namespace metricmap::distributed {

namespace {

/// Each rank sends every owner the cells of its tiles; each owner reduces its tiles, in
/// source-rank order (deterministic sums).
GridAccumulator ownedCells(const GridAccumulator& local) {
  const int size = worldSize();
  const Received incoming = exchangeBuffers(local.serializeByOwner(static_cast<unsigned>(size)));
  GridAccumulator owned(local.cellSize());
  for (int k = 0; k < size; ++k) {
    owned.merge(GridAccumulator::deserialize(incoming.data(k), incoming.size[k],
                                             "grid cells from rank " + std::to_string(k)));
  }
  return owned;
}

}  // namespace

GridSummary reduceGridSummary(const GridAccumulator& local) {
  const GridSummary mine = (worldSize() == 1 ? local : ownedCells(local)).summary();
  constexpr std::int64_t kHuge = std::numeric_limits<std::int64_t>::max();
  std::vector<std::uint64_t> sums = {mine.input_points, mine.skipped_points, mine.points,
                                     mine.cells};
  std::vector<std::int64_t> lo(3, kHuge), hi(3, -kHuge);
  if (mine.cells > 0) {
    lo.assign(mine.min_index.begin(), mine.min_index.end());
    hi.assign(mine.max_index.begin(), mine.max_index.end());
  }
  if (worldSize() > 1) {
    sumToRoot(sums);
    minToRoot(lo);
    maxToRoot(hi);
  }
  if (worldRank() != 0) return GridSummary();
  GridSummary all;
  all.input_points = sums[0];
  all.skipped_points = sums[1];
  all.points = sums[2];
  all.cells = sums[3];
  for (int a = 0; a < 3; ++a) {
    all.min_index[a] = lo[a];
    all.max_index[a] = hi[a];
  }
  return all;
}

GridAccumulator reduceGrid(const GridAccumulator& local) {
  const int size = worldSize();
  if (size == 1) return local;  // nothing to exchange
  const GridAccumulator owned = ownedCells(local);
  // 3. rank 0 gathers the owners' disjoint cells
  const Received gathered = gatherBuffers(owned.serialize());
  GridAccumulator all(local.cellSize());
  for (std::size_t k = 0; k < gathered.ranks(); ++k) {
    all.merge(GridAccumulator::deserialize(gathered.data(k), gathered.size[k],
                                           "reduced grid cells of rank " + std::to_string(k)));
  }
  return all;
}

}  // namespace metricmap::distributed
