// SplitAndMerge vs sequential RANSAC (pcl::SACSegmentation, SACMODEL_LINE) on the 641 real
// URG-04LX scans of exp2.dat, and how many RANSAC lines a Split & Merge segment matches.
#include <cmath>

#include <pcl/ModelCoefficients.h>
#include <pcl/filters/extract_indices.h>
#include <pcl/sample_consensus/method_types.h>
#include <pcl/sample_consensus/model_types.h>
#include <pcl/segmentation/sac_segmentation.h>

#include "bench_common.h"
#include "metricmap/io/laser_scan.h"
#include "metricmap/lines/split_and_merge.h"

namespace metricmap::bench {
namespace {

constexpr double kDistance = 0.03;     // d_th and the RANSAC inlier distance, metres
constexpr std::size_t kMinPoints = 8;  // purge / stop RANSAC below this many points
constexpr double kMatchAngle = 5.0 * M_PI / 180.0;
constexpr double kMatchOffset = 0.05;

struct Scans {
  std::vector<pcl::PointCloud<pcl::PointXYZ>::Ptr> ordered;  // one point per beam, NaN invalid
  std::vector<pcl::PointCloud<pcl::PointXYZ>::Ptr> valid;    // finite points only
};

const Scans& mines() {
  static Scans s = [] {
    Scans out;
    const ScanLog log =
        readScanLines(std::string(METRICMAP_DATA_DIR) + "/breezyslam_mines_urg04lx/exp2.dat",
                      urg04lxMinesFormat());
    for (const LaserScan& scan : log.scans) {
      auto cloud = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>(scanToCloud(scan));
      auto valid = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
      for (const auto& p : *cloud) {
        if (std::isfinite(p.x)) valid->push_back(p);
      }
      out.ordered.push_back(cloud);
      out.valid.push_back(valid);
    }
    return out;
  }();
  return s;
}

SplitAndMergeParams params() {
  SplitAndMergeParams p;
  p.distance_threshold = kDistance;
  p.angle_threshold = 5.0 * M_PI / 180.0;
  p.min_points = kMinPoints;
  p.min_length = 0.1;
  p.max_gap = 0.2;
  return p;
}

struct RansacLine {
  Eigen::Vector2d point, dir;
};

std::vector<RansacLine> sequentialRansac(const pcl::PointCloud<pcl::PointXYZ>::Ptr& scan) {
  std::vector<RansacLine> lines;
  pcl::SACSegmentation<pcl::PointXYZ> sac;
  sac.setModelType(pcl::SACMODEL_LINE);
  sac.setMethodType(pcl::SAC_RANSAC);
  sac.setDistanceThreshold(kDistance);
  sac.setMaxIterations(200);
  auto rest = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>(*scan);
  while (rest->size() >= kMinPoints && lines.size() < 30) {
    pcl::PointIndices inliers;
    pcl::ModelCoefficients coeffs;
    sac.setInputCloud(rest);
    sac.segment(inliers, coeffs);
    if (inliers.indices.size() < kMinPoints) break;
    lines.push_back({Eigen::Vector2d(coeffs.values[0], coeffs.values[1]),
                     Eigen::Vector2d(coeffs.values[3], coeffs.values[4]).normalized()});
    pcl::ExtractIndices<pcl::PointXYZ> extract;
    extract.setInputCloud(rest);
    extract.setIndices(std::make_shared<pcl::PointIndices>(inliers));
    extract.setNegative(true);
    auto next = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
    extract.filter(*next);
    rest = next;
  }
  return lines;
}

bool matches(const RansacLine& line, const LineSegment& s) {
  if (s.length() == 0.0) return false;
  const Eigen::Vector2d d = (s.end - s.start) / s.length();
  const double angle = std::acos(std::min(1.0, std::fabs(d.dot(line.dir))));  // undirected
  const Eigen::Vector2d mid = (s.start + s.end) / 2;
  const Eigen::Vector2d n(-line.dir.y(), line.dir.x());
  return angle < kMatchAngle && std::fabs(n.dot(mid - line.point)) < kMatchOffset;
}

void BM_SplitAndMergeUrg(benchmark::State& state) {
  const Scans& s = mines();
  SplitAndMerge<pcl::PointXYZ> sam;
  sam.setParams(params());
  std::vector<LineSegment> segs;
  std::vector<pcl::PointIndices> members;
  std::size_t total = 0;
  for (auto _ : state) {
    total = 0;
    for (const auto& scan : s.ordered) {
      sam.setInputCloud(scan);
      sam.segment(segs, members);
      total += segs.size();
    }
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * s.ordered.size()));
  state.counters["scans_per_second"] = benchmark::Counter(
      static_cast<double>(s.ordered.size()), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["segments"] = static_cast<double>(total);
}

void BM_SequentialRansacUrg(benchmark::State& state) {
  const Scans& s = mines();
  std::size_t total = 0, matched = 0;
  SplitAndMerge<pcl::PointXYZ> sam;
  sam.setParams(params());
  std::vector<LineSegment> segs;
  std::vector<pcl::PointIndices> members;
  for (auto _ : state) {
    total = matched = 0;
    for (std::size_t k = 0; k < s.valid.size(); ++k) {
      const std::vector<RansacLine> lines = sequentialRansac(s.valid[k]);
      state.PauseTiming();
      sam.setInputCloud(s.ordered[k]);
      sam.segment(segs, members);
      for (const RansacLine& l : lines) {
        ++total;
        for (const LineSegment& seg : segs) {
          if (matches(l, seg)) {
            ++matched;
            break;
          }
        }
      }
      state.ResumeTiming();
    }
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * s.valid.size()));
  state.counters["scans_per_second"] = benchmark::Counter(
      static_cast<double>(s.valid.size()), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["ransac_lines"] = static_cast<double>(total);
  state.counters["matched_fraction"] =
      total ? static_cast<double>(matched) / static_cast<double>(total) : 0.0;
}

BENCHMARK(BM_SplitAndMergeUrg)->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK(BM_SequentialRansacUrg)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace
}  // namespace metricmap::bench
