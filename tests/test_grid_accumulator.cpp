// GridAccumulator: grids of parts of real scans, serialised and merged (in any order, split by
// owner), equal the one-process grid of the whole input; corrupt buffers are refused.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <map>
#include <tuple>

#include "metricmap/common/tile_owner.h"
#include "metricmap/exceptions.h"
#include "metricmap/grid/grid_accumulator.h"
#include "metricmap/grid/occupancy_grid.h"
#include "metricmap/io/cloud_reader.h"
#include "test_data.h"

namespace metricmap {
namespace {

using Cloud = pcl::PointCloud<pcl::PointXYZ>;

Cloud::Ptr load(const std::string& path) {
  auto cloud = std::make_shared<Cloud>();
  loadCloud(path, *cloud);
  return cloud;
}

GridResult worldGrid(const Cloud::Ptr& cloud, float cell) {
  OccupancyGrid<pcl::PointXYZ> grid;
  grid.setCellSize(cell);
  grid.setOrigin(GridOrigin::WorldAligned);
  grid.setInputCloud(cloud);
  grid.compute();
  return {grid.getLayout(), grid.getCells(), grid.getStatistics()};
}

std::vector<Cloud::Ptr> studyParts() {
  std::vector<Cloud::Ptr> parts;
  for (const char* name : {"ciencias000", "museo000", "poli000", "poli001"})
    parts.push_back(load(studyScan(name)));
  // one more part cut out of a scan: cells straddle the cut
  const Cloud::Ptr bunny = load(dataPath("pcl_test_pcd/bunny.pcd"));
  auto a = std::make_shared<Cloud>(), b = std::make_shared<Cloud>();
  for (std::size_t i = 0; i < bunny->size(); ++i) (i % 3 == 0 ? a : b)->push_back((*bunny)[i]);
  parts.push_back(a);
  parts.push_back(b);
  return parts;
}

void expectSameGrid(const GridResult& whole, const GridResult& merged) {
  EXPECT_EQ(merged.stats.points, whole.stats.points);
  EXPECT_EQ(merged.stats.skipped_points, whole.stats.skipped_points);
  EXPECT_EQ(merged.stats.total_cells, whole.stats.total_cells);
  EXPECT_EQ(merged.stats.occupied_cells, whole.stats.occupied_cells);
  EXPECT_EQ(merged.stats.empty_cells, whole.stats.empty_cells);
  EXPECT_EQ(merged.stats.mean_points_per_occupied_cell, whole.stats.mean_points_per_occupied_cell);
  EXPECT_EQ(merged.layout.min_index, whole.layout.min_index);
  EXPECT_EQ(merged.layout.dims, whole.layout.dims);
  EXPECT_EQ(merged.layout.cell_size, whole.layout.cell_size);
  ASSERT_EQ(merged.cells.size(), whole.cells.size());
  std::size_t bad = 0, several = 0;
  double worst = 0.0;
  for (std::size_t i = 0; i < whole.cells.size(); ++i) {
    const GridCell& w = whole.cells[i];
    const GridCell& m = merged.cells[i];
    bad += (w.index != m.index || w.count != m.count) ? 1 : 0;
    several += w.count > 1 ? 1 : 0;
    for (int a = 0; a < 3; ++a) {
      const double rel = std::abs(w.mean[a] - m.mean[a]) / std::abs(w.mean[a]);
      if (w.mean[a] != m.mean[a]) worst = std::max(worst, rel);
    }
  }
  EXPECT_EQ(bad, 0u);
  EXPECT_LE(worst, 1e-12);
  EXPECT_GT(several, 1000u);  // the sums are really tested
}

TEST(GridAccumulator, MergedPartsEqualTheWholeGrid) {
  const std::vector<Cloud::Ptr> parts = studyParts();
  auto whole = std::make_shared<Cloud>();
  std::uint64_t input = 0;
  for (const Cloud::Ptr& p : parts) {
    *whole += *p;
    input += p->size();
  }
  for (float cell : {0.05f, 0.3f}) {
    SCOPED_TRACE(cell);
    const GridResult one = worldGrid(whole, cell);
    // every part through a buffer, merged in reverse order
    GridAccumulator merged(cell);
    for (std::size_t k = parts.size(); k-- > 0;) {
      GridAccumulator part(cell);
      part.add(worldGrid(parts[k], cell), parts[k]->size());
      const std::vector<std::uint8_t> bytes = part.serialize();
      merged.merge(GridAccumulator::deserialize(bytes.data(), bytes.size(), "part"));
    }
    EXPECT_EQ(merged.inputPoints(), input);
    expectSameGrid(one, merged.result());
  }
}

// Parts added in order are reduced as a plain reference reduces them: cells with the same index
// summed in the order they were added, bit for bit, for few parts (sorted runs merged) and for
// many (more runs than are merged: sorted).
TEST(GridAccumulator, PartsReduceInTheOrderTheyWereAdded) {
  const Cloud::Ptr scan = load(dataPath("kitti_odometry_00/sequences/00/velodyne/000000.bin"));
  const float cell = 0.2f;
  for (std::size_t nparts : {3u, 10u, 100u}) {
    SCOPED_TRACE(nparts);
    GridAccumulator acc(cell);
    std::map<std::array<std::int64_t, 3>, CellSum> reference;
    for (std::size_t k = 0; k < nparts; ++k) {
      auto part = std::make_shared<Cloud>();
      for (std::size_t i = k; i < scan->size(); i += nparts) part->push_back((*scan)[i]);
      const GridResult g = worldGrid(part, cell);
      acc.add(g, part->size());
      for (const GridCell& c : g.cells) {
        CellSum& r = reference[c.index];
        r.index = c.index;
        r.count += c.count;
        const double n = static_cast<double>(c.count);
        for (int a = 0; a < 3; ++a) r.sum[a] += c.mean[a] * n;
      }
    }
    const std::vector<CellSum>& cells = acc.cells();
    ASSERT_EQ(cells.size(), reference.size());
    std::size_t bad = 0, several = 0;
    for (const CellSum& c : cells) {
      const auto it = reference.find(c.index);
      ASSERT_NE(it, reference.end());
      bad += (c.count != it->second.count ||
              std::memcmp(c.sum.data(), it->second.sum.data(), sizeof(double) * 3) != 0)
                 ? 1
                 : 0;
      several += c.count > 1 ? 1 : 0;
    }
    EXPECT_EQ(bad, 0u);
    EXPECT_GT(several, 5000u);                        // cells summed from several parts
    for (std::size_t k = 1; k < cells.size(); ++k) {  // linear order: z, then y, then x
      const auto& a = cells[k - 1].index;
      const auto& b = cells[k].index;
      ASSERT_TRUE(std::make_tuple(a[2], a[1], a[0]) < std::make_tuple(b[2], b[1], b[0]));
    }
  }
}

// A buffer that holds its last cell twice (in sorted order) is combined, not taken as two cells.
TEST(GridAccumulator, RepeatedCellInABufferIsCombined) {
  const Cloud::Ptr scan = load(dataPath("pcl_test_pcd/bunny.pcd"));
  GridAccumulator acc(0.01f);
  acc.add(worldGrid(scan, 0.01f), scan->size());
  std::vector<std::uint8_t> bytes = acc.serialize();
  const std::size_t n = acc.cellCount();
  bytes.insert(bytes.end(), bytes.end() - 56, bytes.end());  // the last cell again
  const std::uint64_t twice = n + 1;
  std::memcpy(bytes.data() + 32, &twice, 8);  // the header's cell count
  const GridAccumulator back = GridAccumulator::deserialize(bytes.data(), bytes.size(), "b");
  ASSERT_EQ(back.cellCount(), n);
  EXPECT_EQ(back.cells().back().count, 2 * acc.cells().back().count);
}

// The distributed exchange in one process: every part sends each owner its cells, each owner
// reduces, the owners' results are gathered.
TEST(GridAccumulator, SplitByOwnerThenGatheredEqualsTheWholeGrid) {
  const std::vector<Cloud::Ptr> parts = studyParts();
  auto whole = std::make_shared<Cloud>();
  for (const Cloud::Ptr& p : parts) *whole += *p;
  const float cell = 0.1f;
  for (unsigned owners : {1u, 2u, 3u, 7u}) {
    SCOPED_TRACE(owners);
    std::vector<GridAccumulator> owned(owners, GridAccumulator(cell));
    for (const Cloud::Ptr& p : parts) {
      GridAccumulator acc(cell);
      acc.add(worldGrid(p, cell), p->size());
      const auto buffers = acc.serializeByOwner(owners);
      for (unsigned o = 0; o < owners; ++o)
        owned[o].merge(GridAccumulator::deserialize(buffers[o].data(), buffers[o].size(), "b"));
    }
    GridAccumulator gathered(cell);
    std::size_t cells = 0;
    for (unsigned o = 0; o < owners; ++o) {
      for (const CellSum& c : owned[o].cells())
        ASSERT_EQ(tileOwner(c.index[0], c.index[1], c.index[2], owners), o);
      cells += owned[o].cellCount();
      const auto bytes = owned[o].serialize();
      gathered.merge(GridAccumulator::deserialize(bytes.data(), bytes.size(), "owner"));
    }
    EXPECT_EQ(gathered.cellCount(), cells);  // owners hold disjoint cells
    expectSameGrid(worldGrid(whole, cell), gathered.result());
  }
}

TEST(GridAccumulator, RefusesOtherBuildsAndCellSizes) {
  const Cloud::Ptr cloud = load(studyScan("poli000"));
  OccupancyGrid<pcl::PointXYZ> grid;
  grid.setCellSize(0.1f);
  grid.setInputCloud(cloud);
  grid.compute();  // CloudMinimum: not mergeable
  GridAccumulator acc(0.1f);
  EXPECT_THROW(acc.add({grid.getLayout(), grid.getCells(), grid.getStatistics()}, 1),
               std::invalid_argument);
  EXPECT_THROW(acc.add(worldGrid(cloud, 0.2f), 1), std::invalid_argument);
  GridAccumulator other(0.2f);
  EXPECT_THROW(acc.merge(other), std::invalid_argument);
  EXPECT_THROW(GridAccumulator(0.0f), std::invalid_argument);
}

TEST(GridAccumulator, CorruptBuffersAreRefused) {
  const Cloud::Ptr cloud = load(studyScan("poli000"));
  GridAccumulator acc(0.5f);
  acc.add(worldGrid(cloud, 0.5f), cloud->size());
  ASSERT_GT(acc.cellCount(), 10u);
  const std::vector<std::uint8_t> good = acc.serialize();
  EXPECT_NO_THROW(GridAccumulator::deserialize(good.data(), good.size(), "x"));
  // truncations within the header and the first cells, the last cell, one byte too many
  for (std::size_t n = 0; n < 40 + 3 * 56; ++n)
    EXPECT_THROW(GridAccumulator::deserialize(good.data(), n, "x"), InputError) << n;
  for (std::size_t n = good.size() - 56; n < good.size(); ++n)
    EXPECT_THROW(GridAccumulator::deserialize(good.data(), n, "x"), InputError) << n;
  std::vector<std::uint8_t> bad = good;
  bad.push_back(0);
  EXPECT_THROW(GridAccumulator::deserialize(bad.data(), bad.size(), "x"), InputError);
  auto patched = [&](std::size_t at, std::uint8_t value) {
    std::vector<std::uint8_t> b = good;
    b[at] = value;
    return b;
  };
  try {
    const auto b = patched(0, 'X');  // magic
    GridAccumulator::deserialize(b.data(), b.size(), "rank 2's buffer");
    FAIL() << "bad magic accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("rank 2's buffer"), std::string::npos);
  }
  for (const auto& b : {patched(4, 2),         // another version
                        patched(39, 0x7f)}) {  // a cell count far beyond the buffer
    EXPECT_THROW(GridAccumulator::deserialize(b.data(), b.size(), "x"), InputError);
  }
  // first cell's count set to zero; then its x sum to NaN
  std::vector<std::uint8_t> zero = good;
  std::fill(zero.begin() + 40 + 24, zero.begin() + 40 + 32, 0);
  EXPECT_THROW(GridAccumulator::deserialize(zero.data(), zero.size(), "x"), InputError);
  std::vector<std::uint8_t> nan = good;
  const double q = std::nan("");
  std::memcpy(nan.data() + 40 + 32, &q, 8);
  EXPECT_THROW(GridAccumulator::deserialize(nan.data(), nan.size(), "x"), InputError);
}

}  // namespace
}  // namespace metricmap
