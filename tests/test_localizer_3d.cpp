// Localizer3D on the NCLT keyframes: a map built here from keyframes 0-459 at the reference
// poses, keyframes of the reverse-direction pass localised without an initial pose and compared
// with the reference poses (the oracle); scans of a place outside the map get no fix. And the
// 3D map loader on hostile files.
#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "metricmap/datasets/scan_source.h"
#include "metricmap/exceptions.h"
#include "metricmap/localization/localizer_3d.h"
#include "metricmap/localization/point_map_3d.h"
#include "metricmap/registration/voxel_downsample.h"
#include "shared_data.h"
#include "temp_dir.h"

using namespace metricmap;

namespace {

const std::string kNclt = std::string(METRICMAP_SHARED_DATA_DIR) + "/nclt_2013_01_10_keyframes";

std::vector<Eigen::Vector3f> floats(const pcl::PointCloud<pcl::PointXYZ>& cloud) {
  std::vector<Eigen::Vector3f> out;
  for (const auto& p : cloud) out.emplace_back(p.x, p.y, p.z);
  return out;
}

/// The map of the protocol: keyframes 0-459 at their reference poses, one point per 0.3 m cube.
const PointMap3D& ncltMap(ScanSource& source) {
  static std::unique_ptr<PointMap3D> map;
  if (map) return *map;
  const auto& ref = source.info().reference.poses;
  std::vector<Eigen::Vector3d> world;
  for (std::size_t i = 0; i < 460; ++i)
    for (const auto& p : source.scan(i).points)
      if (std::isfinite(p.x)) world.push_back(ref[i] * Eigen::Vector3d(p.x, p.y, p.z));
  std::vector<Eigen::Vector3f> points;
  for (const auto& p : voxelDownsample(world, 0.3)) points.push_back(p.cast<float>());
  map = std::make_unique<PointMap3D>(pointMap3D(points));
  return *map;
}

double percentile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  return v[static_cast<std::size_t>(q * double(v.size() - 1))];
}

}  // namespace

TEST(Localizer3D, NcltReversePassFromNoPose) {
  SKIP_WITHOUT_SHARED_DATA(kNclt);
  auto source = openScanSource(kNclt);
  const auto& ref = source->info().reference.poses;
  Localizer3D localizer(ncltMap(*source), Localizer3DConfig());
  std::vector<double> dt, dr;
  const std::size_t first = 560, last = 620;
  for (std::size_t i = first; i <= last; ++i) {
    const Localization3D r = localizer.localize(floats(source->scan(i).points));
    if (!r.localised()) continue;
    const Eigen::Isometry3d e = ref[i].inverse() * r.pose;
    dt.push_back((r.pose.translation() - ref[i].translation()).norm());
    dr.push_back(Eigen::AngleAxisd(e.rotation()).angle() * 180.0 / M_PI);
  }
  const Localizer3DStats& s = localizer.stats();
  ASSERT_TRUE(s.first_fix.has_value());
  EXPECT_LT(*s.first_fix, 5u);
  EXPECT_GE(double(s.localised), 0.95 * double(last - first + 1));
  ASSERT_FALSE(dt.empty());
  EXPECT_LE(percentile(dt, 0.5), 0.20);
  EXPECT_LE(percentile(dr, 0.5), 0.8);
  EXPECT_LE(percentile(dt, 0.95), 0.6);
  EXPECT_EQ(s.losses, 0u);
}

TEST(Localizer3D, NcltInitialPoseIsUsed) {
  SKIP_WITHOUT_SHARED_DATA(kNclt);
  auto source = openScanSource(kNclt);
  const auto& ref = source->info().reference.poses;
  Localizer3D localizer(ncltMap(*source), Localizer3DConfig());
  // A guess 1.5 m and 10 degrees off.
  Eigen::Isometry3d guess = ref[600];
  guess.translation() += Eigen::Vector3d(1.0, -1.1, 0.2);
  guess.linear() = Eigen::AngleAxisd(0.17, Eigen::Vector3d::UnitZ()) * guess.linear();
  localizer.setInitialPose(guess);
  const Localization3D r = localizer.localize(floats(source->scan(600).points));
  EXPECT_EQ(r.status, LocalizationStatus::Fixed);
  EXPECT_LT((r.pose.translation() - ref[600].translation()).norm(), 0.4);
  EXPECT_EQ(localizer.stats().global_searches, 0u);
  Eigen::Isometry3d far = ref[600];
  far.translation().x() += 5000.0;
  EXPECT_THROW(localizer.setInitialPose(far), std::invalid_argument);
}

TEST(Localizer3D, NcltScansOfAnotherPlaceGetNoFix) {
  SKIP_WITHOUT_SHARED_DATA(kNclt);
  auto source = openScanSource(kNclt);
  Localizer3D localizer(ncltMap(*source), Localizer3DConfig());
  // Keyframes 700-706 lie 75-80 m from every keyframe of the map.
  for (std::size_t i = 700; i <= 706; ++i) {
    const Localization3D r = localizer.localize(floats(source->scan(i).points));
    EXPECT_FALSE(r.localised()) << "keyframe " << i << " status " << statusName(r.status);
  }
  EXPECT_EQ(localizer.stats().localised, 0u);
}

TEST(PointMap3D, HostileFilesGetOneError) {
  TempDir dir("point_map_3d");
  const std::string nans =
      dir.write("nans.pcd",
                "VERSION .7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n"
                "WIDTH 2\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 2\n"
                "DATA ascii\nnan nan nan\nnan 1 2\n");
  EXPECT_THROW(loadPointMap3D(nans), InputError);
  EXPECT_THROW(loadPointMap3D(dir.write("empty.pcd", "")), InputError);
  EXPECT_THROW(loadPointMap3D(dir.write("junk.bt", "# Octomap OcTree binary file\nres x\n")),
               InputError);
  EXPECT_THROW(loadPointMap3D(dir / "missing.ply"), InputError);
  const std::string far =
      dir.write("far.pcd",
                "VERSION .7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n"
                "WIDTH 2\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 2\n"
                "DATA ascii\n0 0 0\n3e7 0 0\n");
  EXPECT_THROW(loadPointMap3D(far), InputError);
  EXPECT_THROW(pointMap3D({Eigen::Vector3f::Constant(NAN)}), std::invalid_argument);
  const std::string ok = dir.write("ok.pcd",
                                   "VERSION .7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n"
                                   "WIDTH 3\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 3\n"
                                   "DATA ascii\n0 0 0\nnan 0 0\n1 2 3\n");
  const PointMap3D map = loadPointMap3D(ok);
  ASSERT_EQ(map.points.size(), 2u);
  EXPECT_EQ(map.bounds.max(), Eigen::Vector3d(1, 2, 3));
  EXPECT_TRUE(isPointMap3DPath("a/B.PCD") && isPointMap3DPath("m.ot") &&
              !isPointMap3DPath("m.yaml"));
}
