// Maps rebuilt from a trajectory: the same SequenceMapper, given a second trajectory, gives the
// maps a fresh one builds from that trajectory, cell for cell and point for point.
#include <gtest/gtest.h>

#include "metricmap/datasets/scan_source.h"
#include "metricmap/sequence/odometry_run.h"
#include "metricmap/sequence/sequence_mapper.h"

namespace {

const std::string kBalm = std::string(METRICMAP_SHARED_DATA_DIR) + "/balm_realworld_dev";

metricmap::ScanMapperConfig config() {
  metricmap::ScanMapperConfig c;
  c.map_resolution = 0.1;
  c.voxel = 0.2;
  c.min_height = -1.0;
  c.max_height = 1.0;
  metricmap::LogOddsParams l;
  l.resolution = 0.2;
  l.max_range = 20.0;
  c.occupancy = l;
  metricmap::Occupancy2DConfig g;
  g.params.resolution = 0.05;
  c.occupancy_2d = g;
  return c;
}

}  // namespace

TEST(SequenceMapper, RebuildEqualsAFreshBuildWithTheNewTrajectory) {
  auto source = metricmap::openScanSource(kBalm);
  const std::vector<std::size_t> frames = {0, 1, 2, 3, 4, 5, 6, 7};
  const auto reference = metricmap::referenceSensorPoses(*source, frames);
  metricmap::OdometryRunOptions ro;
  ro.frames = frames;
  const auto odometry =
      metricmap::odometrySensorPoses(metricmap::runOdometry(*source, ro), source->info());

  metricmap::SequenceMapper reused(*source, config());
  const metricmap::MapImage first = reused.build(reference, frames).map().image();
  const metricmap::ScanMapper& rebuilt = reused.build(odometry, frames);
  metricmap::SequenceMapper fresh_builder(*source, config());
  const metricmap::ScanMapper& fresh = fresh_builder.build(odometry, frames);

  const metricmap::MapImage a = rebuilt.map().image(), b = fresh.map().image();
  ASSERT_GT(a.width, 0);
  EXPECT_EQ(a.width, b.width);
  EXPECT_EQ(a.height, b.height);
  EXPECT_EQ(a.origin_x, b.origin_x);
  EXPECT_EQ(a.origin_y, b.origin_y);
  EXPECT_EQ(a.hits, b.hits);
  EXPECT_EQ(rebuilt.occupiedCells(), fresh.occupiedCells());
  const auto ca = rebuilt.globalCloud(), cb = fresh.globalCloud();
  ASSERT_EQ(ca.size(), cb.size());
  for (std::size_t i = 0; i < ca.size(); ++i) {
    ASSERT_EQ(ca[i].x, cb[i].x);
    ASSERT_EQ(ca[i].y, cb[i].y);
    ASSERT_EQ(ca[i].z, cb[i].z);
  }
  // the log-odds maps, 3D and 2D: the same cells with the same log-odds bits
  const metricmap::LogOddsMap &la = *rebuilt.occupancy(), &lb = *fresh.occupancy();
  ASSERT_EQ(la.knownVoxels(), lb.knownVoxels());
  ASSERT_GT(la.knownVoxels(), 1000u);
  std::size_t differing = 0;
  la.forEachKnown([&](const metricmap::VoxelKey& k, float l) {
    const auto other = lb.logOdds(k);
    differing += (!other || *other != l) ? 1 : 0;
  });
  EXPECT_EQ(differing, 0u);
  const metricmap::LogOddsGrid2D &ga = *rebuilt.occupancy2D(), &gb = *fresh.occupancy2D();
  ASSERT_GT(ga.knownCells(), 1000u);
  EXPECT_EQ(ga.knownCells(), gb.knownCells());
  EXPECT_EQ(ga.occupiedCells(), gb.occupiedCells());
  std::size_t differing_2d = 0;
  ga.forEachKnown([&](std::int64_t i, std::int64_t j, float l) {
    differing_2d += (gb.state(i, j) == metricmap::CellState::Unknown || gb.logOdds(i, j) != l);
  });
  EXPECT_EQ(differing_2d, 0u);
  const metricmap::MapServerImage ta = ga.probabilityImage(), tb = gb.probabilityImage();
  EXPECT_EQ(ta.width, tb.width);
  EXPECT_EQ(ta.origin_x, tb.origin_x);
  EXPECT_EQ(ta.origin_y, tb.origin_y);
  EXPECT_EQ(ta.pixels, tb.pixels);
  // The two trajectories differ by millimetres, so the maps differ a little but not much: the
  // rebuild did use the new poses.
  EXPECT_NE(first.hits, a.hits);
  EXPECT_THROW(reused.build(odometry, {0, 1}), std::invalid_argument);
}
