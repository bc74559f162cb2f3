// metricmap odometry ROOT --sequence NN --frames A-B: poses from the scans alone (LidarOdometry),
// written in the KITTI pose-file convention, compared per frame with poses/NN.txt when present.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "cli_common.h"
#include "commands.h"
#include "metricmap/datasets/kitti_sequence.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/cloud_reader.h"
#include "metricmap/io/cloud_writer.h"
#include "metricmap/registration/deskew.h"
#include "metricmap/registration/lidar_odometry.h"
#include "metricmap/registration/scan_registration.h"
#include "table.h"

namespace metricmap::cli {
namespace {

struct OdometryOptions {
  std::string root, sequence = "00", frames, out_poses, format = "table";
  bool deskew = false;
  LidarOdometryConfig config;
};

Eigen::Isometry3d inverseOf(const Eigen::Isometry3d& t) {
  Eigen::Isometry3d i;
  i.matrix() = t.matrix().inverse();  // KITTI's Tr is orthonormal only to ~1e-7
  return i;
}

std::string poseLine(const Eigen::Isometry3d& p) {
  std::string line;
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 4; ++col) {
      char num[32];
      std::snprintf(num, sizeof num, "%.9e", p.matrix()(row, col));
      line += (row || col ? " " : "") + std::string(num);
    }
  }
  return line + "\n";
}

void run(const OdometryOptions& o) {
  const auto t_start = std::chrono::steady_clock::now();
  const std::vector<std::size_t> frames = parseFrameList(o.frames);
  const KittiSequence seq{o.root, o.sequence};
  for (std::size_t f : frames) {  // every scan must exist before any work is done
    if (access(seq.scan(f).c_str(), R_OK) != 0) throw InputError(seq.scan(f) + ": missing frame");
  }
  const Eigen::Isometry3d tr = readKittiCalibTr(seq.calib());
  const Eigen::Isometry3d tr_inv = inverseOf(tr);
  // The pose file is optional and only compared against, never used.
  std::vector<Eigen::Isometry3d> reference;
  if (access(seq.poses().c_str(), R_OK) == 0) {
    try {
      reference = readKittiPoses(seq.poses(), *std::max_element(frames.begin(), frames.end()) + 1);
    } catch (const InputError& e) {
      std::fprintf(stderr, "metricmap: warning: %s; no comparison with it\n", e.what());
    }
  }
  LidarOdometryConfig config = o.config;
  config.deskew = o.deskew;
  LidarOdometry odometry(config);
  const bool progress = isatty(STDERR_FILENO) != 0;
  nlohmann::json rows = nlohmann::json::array();
  Table tab({"frame", "x", "y", "z", "step_m", "ms", "iterations", "pairs", "diff_m", "diff_deg"});
  std::string poses_text;
  std::vector<double> ms;
  std::vector<Eigen::Isometry3d> camera;  // KITTI convention: camera 0 of frames[0]
  double load_s = 0.0;
  for (std::size_t k = 0; k < frames.size(); ++k) {
    auto t = std::chrono::steady_clock::now();
    pcl::PointCloud<pcl::PointXYZ> scan;
    loadCloud(seq.scan(frames[k]), scan);
    load_s += secondsSince(t);
    t = std::chrono::steady_clock::now();
    const OdometryResult r =
        o.deskew ? odometry.registerFrame(scan, azimuthTimes(toPoints3d(scan)), seq.scan(frames[k]))
                 : odometry.registerFrame(scan, {}, seq.scan(frames[k]));
    ms.push_back(secondsSince(t) * 1e3);
    camera.push_back(tr * r.pose * tr_inv);
    poses_text += poseLine(camera.back());

    nlohmann::json row = {{"frame", frames[k]},
                          {"pose", std::vector<double>()},
                          {"ms", ms.back()},
                          {"iterations", r.iterations},
                          {"correspondences", r.correspondences},
                          {"source_points", r.points_source},
                          {"threshold", r.threshold},
                          {"degenerate_directions", r.degenerate_directions},
                          {"restarted", r.restarted}};
    for (int i = 0; i < 12; ++i) row["pose"].push_back(camera.back().matrix()(i / 4, i % 4));
    double step = 0.0;
    std::string diff_t = "-", diff_r = "-";
    row["step"] = nullptr;
    row["pose_file_difference"] = nullptr;
    if (k > 0) {
      const Eigen::Isometry3d motion = inverseOf(camera[k - 1]) * camera[k];
      step = motion.translation().norm();
      row["step"] = step;
      if (!reference.empty()) {
        const Eigen::Isometry3d given = inverseOf(reference[frames[k - 1]]) * reference[frames[k]];
        const PoseError e = poseError(given, motion);
        row["pose_file_difference"] = {{"translation", e.translation},
                                       {"rotation_deg", e.rotation_deg}};
        diff_t = fixed(e.translation, 3);
        diff_r = fixed(e.rotation_deg, 3);
      }
    }
    rows.push_back(row);
    const Eigen::Vector3d p = camera.back().translation();
    tab.addRow({std::to_string(frames[k]), fixed(p.x(), 3), fixed(p.y(), 3), fixed(p.z(), 3),
                fixed(step, 3), fixed(ms.back(), 1), std::to_string(r.iterations),
                std::to_string(r.correspondences), diff_t, diff_r});
    if (progress) {
      const double elapsed = secondsSince(t_start);
      std::fprintf(
          stderr, "\rframe %zu/%zu  %.1f ms/scan  %.0f s left   ", k + 1, frames.size(), ms.back(),
          elapsed / static_cast<double>(k + 1) * static_cast<double>(frames.size() - k - 1));
    }
  }
  if (progress) std::fprintf(stderr, "\n");
  if (!o.out_poses.empty()) writeTextAtomic(o.out_poses, poses_text);

  std::vector<double> sorted = ms;
  std::sort(sorted.begin(), sorted.end());
  const double median_ms = sorted[sorted.size() / 2];
  if (o.format == "json") {
    emit(nlohmann::json({{"frames", rows},
                         {"pose_file", reference.empty() ? nlohmann::json(nullptr)
                                                         : nlohmann::json(seq.poses())},
                         {"deskew", o.deskew},
                         {"median_ms_per_scan", median_ms},
                         {"seconds", {{"load", load_s}, {"total", secondsSince(t_start)}}}})
                 .dump(2) +
             "\n",
         "");
    return;
  }
  emitTable(tab, o.format);
  std::printf("%zu frames, median %.1f ms per scan (load excluded), %.2f s in all\n", frames.size(),
              median_ms, secondsSince(t_start));
}

}  // namespace

void addOdometryCommand(CLI::App& app) {
  auto o = std::make_shared<OdometryOptions>();
  CLI::App* sub = app.add_subcommand(
      "odometry", "LiDAR odometry from the scans alone -> poses in KITTI's pose-file convention");
  sub->add_option("root", o->root, "KITTI odometry root (sequences/, optional poses/)")->required();
  sub->add_option("--sequence", o->sequence, "Sequence number")->capture_default_str();
  sub->add_option("--frames", o->frames, "Frames in acquisition order, e.g. 0-100")->required();
  sub->add_flag("--deskew", o->deskew,
                "Correct the motion within each sweep (times from the azimuth, constant velocity)");
  sub->add_option("--out-poses", o->out_poses,
                  "Write the poses: camera 0 in the frame of camera 0 of the first frame, one "
                  "3x4 row-major line per frame, as poses/NN.txt")
      ->check(kOutputFile);
  sub->add_option("--max-range", o->config.max_range, "Drop returns farther (m); local map radius")
      ->check(kFinitePositive)
      ->capture_default_str();
  sub->add_option("--min-range", o->config.min_range, "Drop returns closer (m)")
      ->check(kFiniteNonNegative)
      ->capture_default_str();
  sub->add_option("--voxel-size", o->config.voxel_size, "Local map voxel (m)")
      ->check(kFinitePositive)
      ->capture_default_str();
  sub->add_option("--threads", o->config.threads,
                  "Threads for the scan-to-map pairing (0: all hardware threads); the poses do "
                  "not depend on it")
      ->check(CLI::Range(0u, 1024u))
      ->capture_default_str();
  addFormatOption(*sub, o->format, {"table", "json"});
  sub->callback([o] {
    if (!(o->config.min_range < o->config.max_range)) {
      throw CLI::ValidationError("--min-range", "must be below --max-range");
    }
    try {
      parseFrameList(o->frames);
    } catch (const std::invalid_argument& e) {
      throw CLI::ValidationError("--frames", e.what());
    }
    run(*o);
  });
}

}  // namespace metricmap::cli
