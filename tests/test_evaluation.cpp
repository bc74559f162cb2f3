// Trajectories and their evaluation: the KITTI/TUM/stamp/relation readers and writers, and the
// metrics against hand-computed values (known rotations and translations, a similarity copy that
// aligns to zero, KITTI drift of a straight 1 km path with a known scale error).
#include <cmath>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "metricmap/evaluation/absolute_error.h"
#include "metricmap/evaluation/alignment.h"
#include "metricmap/evaluation/error_statistics.h"
#include "metricmap/evaluation/kitti_drift.h"
#include "metricmap/evaluation/pose_pairing.h"
#include "metricmap/evaluation/relation_error.h"
#include "metricmap/evaluation/relative_error.h"
#include "metricmap/evaluation/rotation_angle.h"
#include "metricmap/evaluation/step_failures.h"
#include "metricmap/evaluation/trajectory_evaluation.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/trajectory.h"
#include "metricmap/io/trajectory_relations.h"
#include "shared_data.h"
#include "temp_dir.h"

namespace {

using metricmap::AlignmentMode;
using metricmap::InputError;
using metricmap::Trajectory;

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;

Eigen::Isometry3d pose(const Eigen::Matrix3d& r, const Eigen::Vector3d& t) {
  Eigen::Isometry3d p = Eigen::Isometry3d::Identity();
  p.linear() = r;
  p.translation() = t;
  return p;
}

Eigen::Matrix3d rotZ(double a) { return Eigen::AngleAxisd(a, Eigen::Vector3d::UnitZ()).matrix(); }

/// A curved, non-planar path with turning orientations (no three positions collinear).
Trajectory helix(std::size_t n, bool stamps) {
  Trajectory t;
  for (std::size_t i = 0; i < n; ++i) {
    const double s = static_cast<double>(i);
    const Eigen::Matrix3d r = (Eigen::AngleAxisd(0.3 * s, Eigen::Vector3d::UnitZ()) *
                               Eigen::AngleAxisd(0.05 * std::sin(s), Eigen::Vector3d::UnitX()))
                                  .toRotationMatrix();
    t.poses.push_back(pose(r, {3.0 * std::cos(0.3 * s), 3.0 * std::sin(0.3 * s), 0.2 * s}));
    if (stamps) t.stamps.push_back(100.0 + 0.1 * s);
  }
  return t;
}

/// Expects `f` to throw InputError whose message contains every one of `needles`.
template <typename F>
void expectInputError(F&& f, std::initializer_list<std::string> needles) {
  try {
    f();
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    for (const std::string& n : needles)
      EXPECT_NE(std::string(e.what()).find(n), std::string::npos) << e.what();
  }
}

// ---- readers and writers --------------------------------------------------------------------

TEST(TrajectoryIo, KittiAndTumRoundTripWithDetection) {
  TempDir dir("traj_io");
  const Trajectory t = helix(7, true);
  metricmap::TrajectoryFormat form{};
  const Trajectory k = metricmap::readTrajectoryFile(
      dir.write("k.txt", "# a comment\n\n" + metricmap::formatKittiTrajectory(t)),
      metricmap::TrajectoryFormat::Auto, &form);
  EXPECT_EQ(form, metricmap::TrajectoryFormat::Kitti);
  EXPECT_FALSE(k.hasStamps());
  const Trajectory u =
      metricmap::readTrajectoryFile(dir.write("u.txt", metricmap::formatTumTrajectory(t)),
                                    metricmap::TrajectoryFormat::Auto, &form);
  EXPECT_EQ(form, metricmap::TrajectoryFormat::Tum);
  ASSERT_EQ(k.size(), t.size());
  ASSERT_EQ(u.size(), t.size());
  for (std::size_t i = 0; i < t.size(); ++i) {
    EXPECT_TRUE(k.poses[i].isApprox(t.poses[i], 1e-8));
    EXPECT_TRUE(u.poses[i].isApprox(t.poses[i], 1e-8));
    EXPECT_NEAR(u.stamps[i], t.stamps[i], 1e-9);
  }
  // Without stamps, TUM lines carry the pose index.
  const Trajectory no_stamps = helix(3, false);
  const std::string text = metricmap::formatTumTrajectory(no_stamps);
  EXPECT_EQ(text.substr(0, 12), "0.000000000 ");
  EXPECT_NE(text.find("\n2.000000000 "), std::string::npos);
}

TEST(TrajectoryIo, TumQuaternionIsXyzw) {
  TempDir dir("traj_q");
  // qz = sin(45 deg), qw = cos(45 deg): a 90 degree turn about z.
  const Trajectory t = metricmap::readTrajectoryFile(
      dir.write("q.txt", "1.5 1 2 3 0 0 0.7071067811865476 0.7071067811865476\n"));
  ASSERT_EQ(t.size(), 1u);
  EXPECT_DOUBLE_EQ(t.stamps[0], 1.5);
  EXPECT_TRUE(t.poses[0].linear().isApprox(rotZ(kPi / 2), 1e-12));
  EXPECT_TRUE(t.poses[0].translation().isApprox(Eigen::Vector3d(1, 2, 3)));
}

TEST(TrajectoryIo, HostileInputNamesFileAndLine) {
  TempDir dir("traj_bad");
  using metricmap::readTrajectoryFile;
  using metricmap::TrajectoryFormat;
  const std::string id = "1 0 0 0 0 1 0 0 0 0 1 0\n";
  expectInputError([&] { readTrajectoryFile(dir / "missing.txt"); }, {"missing.txt"});
  expectInputError([&] { readTrajectoryFile(dir.write("e.txt", "# only\n\n")); },
                   {"e.txt", "no poses"});
  expectInputError([&] { readTrajectoryFile(dir.write("c.txt", id + "1 2 3\n")); },
                   {"c.txt: line 2", "3 values"});
  expectInputError([&] { readTrajectoryFile(dir.write("f.txt", "1 2 3 4 5\n")); },
                   {"f.txt: line 1", "neither"});
  expectInputError(
      [&] { readTrajectoryFile(dir.write("n.txt", id + "1 0 0 nan 0 1 0 0 0 0 1 0\n")); },
      {"n.txt: line 2", "nan"});
  expectInputError([&] { readTrajectoryFile(dir.write("s.txt", "2 0 0 0 0 2 0 0 0 0 2 0\n")); },
                   {"s.txt: line 1", "not a rotation"});
  expectInputError([&] { readTrajectoryFile(dir.write("m.txt", "-1 0 0 0 0 1 0 0 0 0 1 0\n")); },
                   {"m.txt: line 1", "not a rotation"});
  expectInputError([&] { readTrajectoryFile(dir.write("z.txt", "0 1 2 3 0 0 0 0\n")); },
                   {"z.txt: line 1", "quaternion"});
  expectInputError([&] { readTrajectoryFile(dir.write("q.txt", "0 1 2 3 0 0 0 2\n")); },
                   {"q.txt: line 1", "norm 2"});
  expectInputError(
      [&] { readTrajectoryFile(dir.write("o.txt", "1 0 0 0 0 0 0 1\n1 0 0 0 0 0 0 1\n")); },
      {"o.txt: line 2", "increase"});
  expectInputError(
      [&] { readTrajectoryFile(dir.write("k.txt", "0 0 0 0 0 0 0 1\n"), TrajectoryFormat::Kitti); },
      {"k.txt: line 1", "not 12"});
  expectInputError([&] { readTrajectoryFile(dir.path.string()); }, {"not a regular file"});
}

TEST(TrajectoryIo, Stamps) {
  TempDir dir("traj_stamps");
  const auto s = metricmap::readStamps(dir.write("t.txt", "# times\n0\n\n0.5\r\n1e1\n"));
  ASSERT_EQ(s.size(), 3u);
  EXPECT_DOUBLE_EQ(s[2], 10.0);
  EXPECT_TRUE(metricmap::readStamps(dir.write("e.txt", "")).empty());
  expectInputError([&] { metricmap::readStamps(dir.write("d.txt", "0\n1\n1\n")); },
                   {"d.txt: line 3", "increase"});
  expectInputError([&] { metricmap::readStamps(dir.write("two.txt", "0 1\n")); },
                   {"two.txt: line 1", "2 values"});
  expectInputError([&] { metricmap::readStamps(dir.write("x.txt", "0\ninf\n")); },
                   {"x.txt: line 2"});
}

TEST(TrajectoryIo, RelationsRollPitchYaw) {
  TempDir dir("relations");
  const double roll = 0.1, pitch = -0.2, yaw = 0.7;
  const auto r = metricmap::readRelations(
      dir.write("r.txt", "# t1 t2 x y z roll pitch yaw\n10 11 1 2 3 0.1 -0.2 0.7\n"));
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0].stamp1, 10.0);
  EXPECT_EQ(r[0].stamp2, 11.0);
  // Rz(yaw) Ry(pitch) Rx(roll), written out entry by entry.
  const double cr = std::cos(roll), sr = std::sin(roll), cp = std::cos(pitch), sp = std::sin(pitch),
               cy = std::cos(yaw), sy = std::sin(yaw);
  Eigen::Matrix3d m;
  m << cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr,  //
      sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr,   //
      -sp, cp * sr, cp * cr;
  EXPECT_TRUE(r[0].relative.linear().isApprox(m, 1e-12));
  EXPECT_TRUE(r[0].relative.translation().isApprox(Eigen::Vector3d(1, 2, 3)));
  expectInputError([&] { metricmap::readRelations(dir.write("b.txt", "1 2 3\n")); },
                   {"b.txt: line 1", "not 8"});
  expectInputError([&] { metricmap::readRelations(dir.write("n.txt", "1 2 0 0 0 0 0 nan\n")); },
                   {"n.txt: line 1"});
  expectInputError([&] { metricmap::readRelations(dir.write("e.txt", "\n")); }, {"e.txt"});
}

// ---- metrics --------------------------------------------------------------------------------

TEST(Evaluation, RotationAngle) {
  const Eigen::Vector3d axis = Eigen::Vector3d(1, -2, 0.5).normalized();
  for (double a : {0.0, 1e-9, 1e-4, 0.3, 2.0, kPi - 1e-6}) {
    EXPECT_NEAR(metricmap::rotationAngle(Eigen::AngleAxisd(a, axis).matrix()), a, 1e-12) << a;
  }
  EXPECT_NEAR(metricmap::rotationAngleDeg(rotZ(30 * kDeg)), 30.0, 1e-12);
}

TEST(Evaluation, StatisticsByHand) {
  const auto s = metricmap::summarizeErrors({4, 1, 3, 2});
  EXPECT_EQ(s.count, 4u);
  EXPECT_DOUBLE_EQ(s.mean, 2.5);
  EXPECT_DOUBLE_EQ(s.median, 2.5);
  EXPECT_DOUBLE_EQ(s.rmse, std::sqrt(30.0 / 4));
  EXPECT_DOUBLE_EQ(s.stddev, std::sqrt(1.25));
  EXPECT_EQ(s.min, 1.0);
  EXPECT_EQ(s.max, 4.0);
  EXPECT_DOUBLE_EQ(metricmap::summarizeErrors({5, 1, 3}).median, 3.0);
  const auto m = metricmap::meanAndSampleStd({4, 1, 3, 2});
  EXPECT_DOUBLE_EQ(m.mean, 2.5);
  EXPECT_DOUBLE_EQ(m.stddev, std::sqrt(5.0 / 3));
  EXPECT_EQ(metricmap::meanAndSampleStd({7}).stddev, 0.0);
}

TEST(Evaluation, AteByHand) {
  std::vector<Eigen::Isometry3d> ref, est;
  for (int i = 0; i < 3; ++i) {
    ref.push_back(pose(Eigen::Matrix3d::Identity(), {double(i), 0, 0}));
    est.push_back(pose(i == 1 ? rotZ(10 * kDeg) : Eigen::Matrix3d::Identity(),
                       {double(i), 0.1 * (i + 1), 0}));
  }
  const auto e = metricmap::absoluteError(est, ref);
  EXPECT_NEAR(e.translation[0], 0.1, 1e-15);
  EXPECT_NEAR(e.translation[2], 0.3, 1e-15);
  EXPECT_NEAR(e.translation_stats.rmse, std::sqrt((0.01 + 0.04 + 0.09) / 3), 1e-15);
  EXPECT_NEAR(e.translation_stats.mean, 0.2, 1e-15);
  EXPECT_NEAR(e.rotation_deg[1], 10.0, 1e-12);
  EXPECT_NEAR(e.rotation_stats.max, 10.0, 1e-12);
  EXPECT_NEAR(e.rotation_stats.median, 0.0, 1e-12);
}

TEST(Evaluation, RpeByHand) {
  // Reference: 1 m steps along x. Estimate: the first step turns 5 degrees (same translation),
  // the second step is 1.1 m long.
  std::vector<Eigen::Isometry3d> ref, est;
  for (int i = 0; i < 3; ++i) ref.push_back(pose(Eigen::Matrix3d::Identity(), {double(i), 0, 0}));
  est.push_back(Eigen::Isometry3d::Identity());
  est.push_back(pose(rotZ(5 * kDeg), {1, 0, 0}));
  est.push_back(est[1] * pose(Eigen::Matrix3d::Identity(), {1.1, 0, 0}));
  const auto e = metricmap::relativeError(est, ref);
  ASSERT_EQ(e.translation.size(), 2u);
  EXPECT_NEAR(e.translation[0], 0.0, 1e-15);
  EXPECT_NEAR(e.rotation_deg[0], 5.0, 1e-12);
  EXPECT_NEAR(e.translation[1], 0.1, 1e-12);
  EXPECT_NEAR(e.rotation_deg[1], 0.0, 1e-12);
  EXPECT_NEAR(e.translation_stats.rmse, std::sqrt(0.01 / 2), 1e-12);
}

TEST(Evaluation, StepFailuresByHand) {
  // Reference: 1 m steps along x. Estimate: step 0 exact, step 1 turns 4 degrees, step 2 is
  // 0.35 m too long, step 3 turns 2.9 degrees and is 0.29 m too short (within both limits).
  std::vector<Eigen::Isometry3d> ref, est;
  for (int i = 0; i < 5; ++i) ref.push_back(pose(Eigen::Matrix3d::Identity(), {double(i), 0, 0}));
  est.push_back(Eigen::Isometry3d::Identity());
  est.push_back(est.back() * pose(Eigen::Matrix3d::Identity(), {1, 0, 0}));
  est.push_back(est.back() * pose(rotZ(4 * kDeg), {1, 0, 0}));
  est.push_back(est.back() * pose(Eigen::Matrix3d::Identity(), {1.35, 0, 0}));
  est.push_back(est.back() * pose(rotZ(2.9 * kDeg), {0.71, 0, 0}));
  const metricmap::StepFailures f = metricmap::findStepFailures(metricmap::relativeError(est, ref));
  EXPECT_EQ(f.steps, 4u);
  EXPECT_EQ(f.failed, (std::vector<std::size_t>{1, 2}));
  // Tighter limits catch step 3 too.
  const metricmap::StepFailures tight =
      metricmap::findStepFailures(metricmap::relativeError(est, ref), {0.2, 2.0});
  EXPECT_EQ(tight.failed, (std::vector<std::size_t>{1, 2, 3}));
  // evaluateTrajectory reports the same steps.
  Trajectory te, tr;
  te.poses = est;
  tr.poses = ref;
  metricmap::EvaluationConfig none;
  none.alignment = AlignmentMode::None;  // collinear reference positions
  EXPECT_EQ(metricmap::evaluateTrajectory(te, tr, none).steps.failed, f.failed);
  EXPECT_THROW(metricmap::findStepFailures({}, {0.0, 3.0}), std::invalid_argument);
  EXPECT_THROW(metricmap::findStepFailures({}, {0.3, std::nan("")}), std::invalid_argument);
}

TEST(Evaluation, SimilarityCopyAlignsToZero) {
  const Trajectory ref = helix(30, false);
  const Eigen::Matrix3d r =
      Eigen::AngleAxisd(0.8, Eigen::Vector3d(0.2, 1, -0.4).normalized()).toRotationMatrix();
  const Eigen::Vector3d t(5, -3, 2);
  const double s = 0.37;
  Trajectory est;
  for (const auto& p : ref.poses)
    est.poses.push_back(pose(r * p.linear(), s * (r * p.translation()) + t));

  metricmap::EvaluationConfig c;
  c.alignment = AlignmentMode::Similarity;
  const auto ev = metricmap::evaluateTrajectory(est, ref, c);
  EXPECT_EQ(ev.pairs.mode, metricmap::PairingMode::Index);
  EXPECT_NEAR(ev.alignment.scale, 1.0 / s, 1e-9);
  EXPECT_TRUE(ev.alignment.rotation.isApprox(r.transpose(), 1e-9));
  EXPECT_LT(ev.ate.translation_stats.max, 1e-9);
  EXPECT_LT(ev.ate.rotation_stats.max, 1e-6);
  EXPECT_LT(ev.rpe.translation_stats.max, 1e-9);
  EXPECT_LT(ev.rpe.rotation_stats.max, 1e-6);

  // Rigid alignment cannot undo the scale; a rigid copy aligns to zero with it.
  c.alignment = AlignmentMode::Rigid;
  EXPECT_GT(metricmap::evaluateTrajectory(est, ref, c).ate.translation_stats.rmse, 0.5);
  Trajectory rigid;
  for (const auto& p : ref.poses)
    rigid.poses.push_back(pose(r * p.linear(), r * p.translation() + t));
  const auto er = metricmap::evaluateTrajectory(rigid, ref, c);
  EXPECT_EQ(er.alignment.scale, 1.0);
  EXPECT_LT(er.ate.translation_stats.max, 1e-9);
  EXPECT_LT(er.ate.rotation_stats.max, 1e-6);
  // No alignment: the ATE is the plain distance of the copies.
  c.alignment = AlignmentMode::None;
  const auto en = metricmap::evaluateTrajectory(rigid, ref, c);
  EXPECT_NEAR(en.ate.translation[0],
              (r * ref.poses[0].translation() + t - ref.poses[0].translation()).norm(), 1e-12);
}

TEST(Evaluation, RigidAlignmentIsLeastSquares) {
  // With noise, no small change of the alignment lowers the sum of squared distances.
  const Trajectory ref = helix(40, false);
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 0.05);
  std::vector<Eigen::Isometry3d> est;
  for (const auto& p : ref.poses) {
    est.push_back(pose(p.linear(), rotZ(0.4) * p.translation() +
                                       Eigen::Vector3d(1 + noise(rng), noise(rng), noise(rng))));
  }
  const auto a = metricmap::alignPositions(est, ref.poses, AlignmentMode::Rigid);
  auto cost = [&](const metricmap::Alignment& al) {
    double c = 0;
    for (std::size_t i = 0; i < est.size(); ++i)
      c += (al.apply(est[i]).translation() - ref.poses[i].translation()).squaredNorm();
    return c;
  };
  const double best = cost(a);
  for (int k = 0; k < 6; ++k) {
    for (double sign : {-1.0, 1.0}) {
      metricmap::Alignment b = a;
      if (k < 3) {
        b.rotation = Eigen::AngleAxisd(sign * 1e-3, Eigen::Vector3d::Unit(k)) * a.rotation;
      } else {
        b.translation[k - 3] += sign * 1e-3;
      }
      EXPECT_GT(cost(b), best);
    }
  }
  std::vector<Eigen::Isometry3d> line;
  for (int i = 0; i < 5; ++i) line.push_back(pose(Eigen::Matrix3d::Identity(), {double(i), 0, 0}));
  EXPECT_THROW(metricmap::alignPositions(line, line, AlignmentMode::Rigid), std::invalid_argument);
  EXPECT_NO_THROW(metricmap::alignPositions(line, line, AlignmentMode::None));
}

/// A straight path along x of `n` poses, `step` metres apart, orientations from `yaw_per_m`.
std::vector<Eigen::Isometry3d> straight(std::size_t n, double step, double scale = 1.0,
                                        double yaw_per_m = 0.0) {
  std::vector<Eigen::Isometry3d> p;
  for (std::size_t i = 0; i < n; ++i) {
    const double x = step * static_cast<double>(i);
    p.push_back(pose(rotZ(yaw_per_m * x), {scale * x, 0, 0}));
  }
  return p;
}

TEST(Evaluation, KittiDriftOfAConstantScaleError) {
  // 1 km in 1000 steps a hair over 1 m: a segment of L metres ends exactly L / 1 m frames on
  // (the devkit takes the first frame *beyond* L), so an estimate 2 % too long drifts 2 %.
  const double step = 1.0 + 1e-9;
  const auto ref = straight(1001, step);
  const auto est = straight(1001, step, 1.02);
  const auto d = metricmap::kittiDrift(est, ref);
  EXPECT_NEAR(d.path_length, 1000 * step, 1e-9);
  std::size_t total = 0;
  for (const auto& l : d.lengths) {
    // Starts every 10 frames up to 1000 - L.
    const auto expected = static_cast<std::size_t>((1000 - l.length) / 10) + 1;
    EXPECT_EQ(l.segments, expected) << l.length;
    EXPECT_NEAR(l.translation_percent, 2.0, 1e-6) << l.length;
    EXPECT_NEAR(l.rotation_deg_per_m, 0.0, 1e-6);
    total += expected;
  }
  EXPECT_EQ(d.segments, total);
  EXPECT_EQ(total, 448u);
  EXPECT_NEAR(d.translation_percent, 2.0, 1e-6);
  EXPECT_NEAR(d.rotation_deg_per_m, 0.0, 1e-6);
}

TEST(Evaluation, KittiDriftOfAConstantTurnRate) {
  const double step = 1.0 + 1e-9, rate = 0.01 * kDeg;  // 0.01 degree per metre
  const auto d = metricmap::kittiDrift(straight(1001, step, 1.0, rate), straight(1001, step));
  EXPECT_NEAR(d.rotation_deg_per_m, 0.01, 1e-8);
  for (const auto& l : d.lengths) EXPECT_NEAR(l.rotation_deg_per_m, 0.01, 1e-8);
}

TEST(Evaluation, KittiDriftOfAShortRunHasNoSegment) {
  const auto d = metricmap::kittiDrift(straight(100, 1.0, 1.5), straight(100, 1.0));
  EXPECT_EQ(d.segments, 0u);
  EXPECT_NEAR(d.path_length, 99.0, 1e-12);
  EXPECT_EQ(d.translation_percent, 0.0);
}

TEST(Evaluation, PairingByIndexAndByStamps) {
  Trajectory est = helix(10, true), ref = helix(10, true);
  for (double& s : ref.stamps) s += 0.004;  // within evo's default 0.01 s
  ref.stamps.erase(ref.stamps.begin() + 3);
  ref.poses.erase(ref.poses.begin() + 3);
  auto p = metricmap::pairPoses(est, ref);
  EXPECT_EQ(p.mode, metricmap::PairingMode::Stamps);
  ASSERT_EQ(p.size(), 9u);  // every reference stamp finds its estimate
  EXPECT_EQ(p.reference[3], 3u);
  EXPECT_EQ(p.estimate[3], 4u);
  EXPECT_THROW(metricmap::pairPoses(est, ref, 0.001), std::invalid_argument);
  // One side without stamps: by index, which needs the same count.
  Trajectory kitti = helix(10, false);
  EXPECT_EQ(metricmap::pairPoses(kitti, est).mode, metricmap::PairingMode::Index);
  EXPECT_THROW(metricmap::pairPoses(kitti, ref), std::invalid_argument);
  EXPECT_EQ(metricmap::nearestStamp({0.0, 1.0, 2.0}, 1.4, 0.5), 1u);
  EXPECT_EQ(metricmap::nearestStamp({0.0, 1.0, 2.0}, 1.5, 0.5), 1u);  // a tie: the earlier
  EXPECT_EQ(metricmap::nearestStamp({0.0, 1.0, 2.0}, 2.6, 0.5), 3u);
}

TEST(Evaluation, RelationMetricByHand) {
  Trajectory est;
  est.stamps = {0.0, 1.0, 2.0};
  est.poses = {Eigen::Isometry3d::Identity(), pose(rotZ(kPi / 2), {1, 0, 0}),
               pose(rotZ(kPi / 2), {1, 1, 0})};
  std::vector<metricmap::PoseRelation> rel(3);
  // 0 -> 1 exactly as estimated, given at a stamp 5 ms off.
  rel[0].stamp1 = 0.005;
  rel[0].stamp2 = 1.0;
  rel[0].relative = pose(rotZ(kPi / 2), {1, 0, 0});
  // 0 -> 2: estimated (1, 1, 0) and 90 degrees; given (1, 1.3, 0) and 80 degrees.
  rel[1].stamp1 = 0.0;
  rel[1].stamp2 = 2.0;
  rel[1].relative = pose(rotZ(80 * kDeg), {1, 1.3, 0});
  rel[2].stamp1 = 5.0;  // not in the estimate
  rel[2].stamp2 = 6.0;
  const auto e = metricmap::relationError(est, rel);
  EXPECT_EQ(e.used, 2u);
  ASSERT_EQ(e.skipped.size(), 1u);
  EXPECT_EQ(e.skipped[0], 2u);
  // E = given^-1 * estimated: translation R(80)^T ((1,1,0) - (1,1.3,0)), length 0.3.
  EXPECT_NEAR(e.translation[0], 0.0, 1e-12);
  EXPECT_NEAR(e.translation[1], 0.3, 1e-12);
  EXPECT_NEAR(e.rotation_deg[1], 10.0, 1e-10);
  EXPECT_NEAR(e.translation_abs.mean, 0.15, 1e-12);
  EXPECT_NEAR(e.translation_abs.stddev, std::sqrt(2 * 0.15 * 0.15), 1e-12);
  EXPECT_NEAR(e.translation_sq.mean, 0.045, 1e-12);
  EXPECT_NEAR(e.translation_sq.stddev, std::sqrt(2 * 0.045 * 0.045), 1e-12);
  EXPECT_NEAR(e.rotation_abs_deg.mean, 5.0, 1e-10);
  EXPECT_NEAR(e.rotation_sq_deg.mean, 50.0, 1e-8);
  EXPECT_NEAR(e.rotation_sq_deg.stddev, std::sqrt(2 * 50.0 * 50.0), 1e-8);
  // A 1 ms tolerance misses the relation given 5 ms off.
  EXPECT_EQ(metricmap::relationError(est, rel, 0.001).used, 1u);
  EXPECT_THROW(metricmap::relationError(helix(3, false), rel), std::invalid_argument);
}

TEST(Evaluation, RealPairSimilarityCopy) {
  // BALM's real hand-carried trajectory (KITTI form): a similarity copy aligns to zero.
  const std::string path =
      std::string(METRICMAP_SOURCE_DIR) + "/../shared/data/balm_realworld_dev/poses.txt";
  SKIP_WITHOUT_SHARED_DATA(path);
  const Trajectory ref = metricmap::readTrajectoryFile(path);
  ASSERT_EQ(ref.size(), 40u);
  Trajectory est;
  const Eigen::Matrix3d r = Eigen::AngleAxisd(2.0, Eigen::Vector3d(1, 1, 1).normalized()).matrix();
  for (const auto& p : ref.poses) {
    Eigen::Isometry3d q = Eigen::Isometry3d::Identity();
    q.linear() = r * p.linear();
    q.translation() = 1.7 * (r * p.translation()) + Eigen::Vector3d(-4, 9, 1);
    est.poses.push_back(q);
  }
  metricmap::EvaluationConfig c;
  c.alignment = AlignmentMode::Similarity;
  const auto ev = metricmap::evaluateTrajectory(est, ref, c);
  EXPECT_NEAR(ev.alignment.scale, 1 / 1.7, 1e-9);
  EXPECT_LT(ev.ate.translation_stats.max, 1e-8);
  EXPECT_LT(ev.rpe.translation_stats.max, 1e-8);
  EXPECT_LT(ev.rpe.rotation_stats.max, 1e-5);
  EXPECT_EQ(ev.drift.segments, 0u);  // 19.7 m: no 100 m segment
}

}  // namespace
