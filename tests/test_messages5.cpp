// Messages name what happened: which scan lacks per-point times and which has them (the first
// scan without times made the second "missing" them), and numbers in their shortest form (a
// pairing tolerance of 0.01 s was printed "0.010000").
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "metricmap/datasets/scan_source.h"
#include "metricmap/evaluation/pose_pairing.h"
#include "metricmap/exceptions.h"
#include "metricmap/sequence/odometry_run.h"

namespace metricmap {
namespace {

/// Two ring scans in memory; `timed[k]` says whether scan k carries per-point times.
class TwoScans : public ScanSource {
 public:
  explicit TwoScans(std::vector<bool> timed) : timed_(std::move(timed)) { info_.kind = "folder"; }
  std::size_t size() const override { return timed_.size(); }
  const SourceInfo& info() const override { return info_; }
  Scan scan(std::size_t i) override {
    Scan s;
    s.index = i;
    s.name = "scan" + std::to_string(i);
    for (int k = 0; k < 600; ++k) {
      const float a = 6.2831853f * static_cast<float>(k) / 600.0f;
      s.points.push_back(
          {8.0f * std::cos(a), 8.0f * std::sin(a), 0.3f * static_cast<float>(k % 5)});
      if (timed_[i]) s.point_times.push_back(0.1 * k / 600.0);
    }
    return s;
  }

 private:
  std::vector<bool> timed_;
  SourceInfo info_;
};

TEST(Messages, PerPointTimesNameTheScanAndWhatItHas) {
  struct Case {
    std::vector<bool> timed;
    std::string needle;
  };
  for (const Case& c : std::vector<Case>{
           {{false, true}, "scan1: per-point times present, where the first scan had none"},
           {{true, false}, "scan1: per-point times missing, unlike the first scan's"}}) {
    SCOPED_TRACE(c.needle);
    TwoScans source(c.timed);
    OdometryRunOptions options;
    options.world = WorldFrame::FirstScan;  // a ring of points: no ground to level by
    try {
      runOdometry(source, options);
      ADD_FAILURE() << "ran";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(c.needle), std::string::npos) << e.what();
    }
  }
}

TEST(Messages, PairingToleranceInItsShortestForm) {
  Trajectory est, ref;
  for (int k = 0; k < 3; ++k) {
    est.stamps.push_back(k);
    ref.stamps.push_back(k + 0.5);
    est.poses.push_back(Eigen::Isometry3d::Identity());
    ref.poses.push_back(Eigen::Isometry3d::Identity());
  }
  for (const double tol : {0.01, 0.1, 1e-7}) {
    try {
      pairPoses(est, ref, tol);
      ADD_FAILURE() << "paired";
    } catch (const std::invalid_argument& e) {
      const std::string w = e.what();
      const std::string shown = tol == 0.01  ? "within 0.01 s"
                                : tol == 0.1 ? "within 0.1 s"
                                             : "within 1e-07 s";
      EXPECT_NE(w.find(shown), std::string::npos) << w;
    }
  }
}

}  // namespace
}  // namespace metricmap
