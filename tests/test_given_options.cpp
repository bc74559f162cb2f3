// A value given for the odometry's range window is never replaced by the sensor profile: a
// given min_range at or above the window's maximum is refused (it ran with min_range 0), only a
// min_range the profile chose yields to a given max_range.
#include <cmath>
#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include <Eigen/Core>

#include <gtest/gtest.h>

#include "metricmap/datasets/scan_source.h"
#include "metricmap/sequence/odometry_run.h"
#include "metricmap/sequence/sensor_profile.h"
#include "temp_dir.h"

namespace metricmap {
namespace {

struct ProfileCase {
  const char* what;
  bool auto_max, auto_min, auto_voxel;
  double given_max, given_min;  ///< used where not automatic
  bool refused;
  double max_range, min_range;  ///< expected when accepted
};

// The profile below: max_range 30 m, min_range 3 m (written out, not computed by the code).
const std::vector<ProfileCase> kCases = {
    {"given min above the chosen max", true, false, true, 0, 50, true, 0, 0},
    {"given min equal to the chosen max", true, false, true, 0, 30, true, 0, 0},
    {"given min below the chosen max", true, false, true, 0, 2, false, 30, 2},
    {"given min 0", true, false, true, 0, 0, false, 30, 0},
    {"chosen min above the given max", false, true, true, 2, 0, false, 2, 0},
    {"chosen min below the given max", false, true, true, 20, 0, false, 20, 3},
    {"both given, min above max, voxel chosen", false, false, true, 1, 2, true, 0, 0},
    {"both given, min below max, voxel chosen", false, false, true, 5, 1, false, 5, 1},
    {"both chosen", true, true, true, 0, 0, false, 30, 3},
};

TEST(GivenOptions, TheProfileNeverReplacesAGivenMinRange) {
  SensorProfile profile;
  profile.used = true;
  profile.max_range = 30.0;
  profile.min_range = 3.0;
  profile.voxel_size = 0.4;
  profile.coarse_voxel_size = 1.2;
  profile.max_threshold = 0.8;
  for (const ProfileCase& c : kCases) {
    SCOPED_TRACE(c.what);
    LidarOdometryConfig config;
    if (!c.auto_max) config.max_range = c.given_max;
    if (!c.auto_min) config.min_range = c.given_min;
    SensorProfileRequest request;
    request.max_range = c.auto_max;
    request.min_range = c.auto_min;
    request.voxel_size = c.auto_voxel;
    if (c.refused) {
      try {
        applyProfile(config, profile, request);
        ADD_FAILURE() << "accepted";
      } catch (const std::invalid_argument& e) {
        const std::string w = e.what();
        EXPECT_NE(w.find("min_range"), std::string::npos) << w;
        EXPECT_NE(w.find("given"), std::string::npos) << w;
      }
    } else {
      const LidarOdometryConfig out = applyProfile(config, profile, request);
      EXPECT_EQ(out.max_range, c.max_range);
      EXPECT_EQ(out.min_range, c.min_range);
    }
  }
}

/// A float32 (n, 3) .npy scan: points on a ring of radius r around the sensor.
void writeRing(const std::string& path, int n, float r) {
  std::string header =
      "{'descr': '<f4', 'fortran_order': False, 'shape': (" + std::to_string(n) + ", 3), }";
  while ((10 + header.size() + 1) % 64 != 0) header += ' ';
  header += '\n';
  std::ofstream out(path, std::ios::binary);
  out.write("\x93NUMPY\x01\x00", 8);
  const auto len = static_cast<std::uint16_t>(header.size());
  out.write(reinterpret_cast<const char*>(&len), 2);
  out << header;
  for (int i = 0; i < n; ++i) {
    const float a = 6.2831853f * static_cast<float>(i) / static_cast<float>(n);
    const float p[3] = {r * std::cos(a), r * std::sin(a), 0.1f * static_cast<float>(i % 7)};
    out.write(reinterpret_cast<const char*>(p), sizeof p);
  }
}

TEST(GivenOptions, RunOdometryRefusesAGivenMinRangeAboveTheChosenWindow) {
  TempDir dir("given_min_range");
  for (int k = 0; k < 2; ++k) writeRing(dir / ("00" + std::to_string(k) + ".npy"), 400, 8.0f);
  const auto source = openScanSource(dir.path.string());
  OdometryRunOptions options;
  options.config.min_range = 50.0;  // given; the ring's profile chooses max_range 10 m
  options.profile.min_range = false;
  try {
    runOdometry(*source, options);
    ADD_FAILURE() << "ran";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("min_range 50 m (given)"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace metricmap

namespace metricmap {
namespace {

// Scans 0.8 s apart (a drive's keyframes) take the keyframe motion model, 0.1 s apart (a
// spinning LiDAR's sweeps) keep the constant-velocity one; a given motion model is kept.
TEST(GivenOptions, TheScanIntervalChoosesTheMotionModel) {
  auto stamps = [](double dt, int n) {
    std::vector<double> s;
    for (int i = 0; i < n; ++i) s.push_back(100.0 + dt * i + (i % 2 ? 0.01 : 0.0));
    return s;
  };
  SensorProfile keyframes, sweeps, unknown;
  profileStamps(keyframes, stamps(0.8, 9));
  profileStamps(sweeps, stamps(0.1, 9));
  profileStamps(unknown, {100.0});
  EXPECT_NEAR(keyframes.scan_interval, 0.8, 0.011);
  EXPECT_TRUE(keyframes.keyframes);
  EXPECT_NEAR(sweeps.scan_interval, 0.1, 0.011);
  EXPECT_FALSE(sweeps.keyframes);
  EXPECT_EQ(unknown.scan_interval, 0.0);
  EXPECT_FALSE(unknown.keyframes);

  const LidarOdometryConfig given;
  SensorProfileRequest request;
  const LidarOdometryConfig k = applyProfile(given, keyframes, request);
  EXPECT_EQ(k.prediction_rotation, 0.0);
  EXPECT_EQ(k.min_support, 1.0);
  EXPECT_EQ(k.hypothesis_count, 3);
  const LidarOdometryConfig s = applyProfile(given, sweeps, request);
  EXPECT_EQ(s.prediction_rotation, given.prediction_rotation);
  EXPECT_EQ(s.min_support, given.min_support);
  request.motion = false;
  const LidarOdometryConfig g = applyProfile(given, keyframes, request);
  EXPECT_EQ(g.prediction_rotation, given.prediction_rotation);
  EXPECT_EQ(g.min_support, given.min_support);
}

}  // namespace
}  // namespace metricmap
