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
  // The two trajectories differ by millimetres, so the maps differ a little but not much: the
  // rebuild did use the new poses.
  EXPECT_NE(first.hits, a.hits);
  EXPECT_THROW(reused.build(odometry, {0, 1}), std::invalid_argument);
}
