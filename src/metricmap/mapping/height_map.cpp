#include "metricmap/mapping/height_map.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

#include "metricmap/common/format_number.h"
#include "metricmap/common/memory_budget.h"
#include "metricmap/common/rigid_transform.h"
#include "metricmap/detail/fast_floor.h"
#include "metricmap/exceptions.h"

namespace metricmap {

HeightMap::HeightMap(const HeightMapParams& params) : params_(params) {
  if (!std::isfinite(params.resolution) || !(params.resolution > 0.0)) {
    throw std::invalid_argument("resolution must be a finite number > 0");
  }
  if (params.map_size == 0) throw std::invalid_argument("map size must be > 0");
  // bins below, between and above: the middle (obstacle) bin needs a floor and a ceiling edge
  if (params.z_bins.size() < 2)
    throw std::invalid_argument("z bins need at least two edges (floor, ceiling), got " +
                                std::to_string(params.z_bins.size()));
  for (std::size_t i = 0; i < params.z_bins.size(); ++i) {
    if (!std::isfinite(params.z_bins[i]) || (i > 0 && !(params.z_bins[i] > params.z_bins[i - 1]))) {
      throw std::invalid_argument("z bins must be finite and strictly increasing");
    }
  }
  const long double cells = static_cast<long double>(params.map_size) * params.map_size * bins();
  const std::string what = "a " + std::to_string(params.map_size) + " x " +
                           std::to_string(params.map_size) + " map with " + std::to_string(bins()) +
                           " height bins";
  if (cells >= 0x1p62L)  // beyond any budget, and beyond what checkMemory counts exactly
    throw CapacityError(what + " needs more than 2^64 bytes, more than the memory budget of " +
                        std::to_string(memoryBudget() >> 20) + " MiB (--max-memory)");
  checkMemory(static_cast<std::uint64_t>(cells), sizeof(std::uint32_t), what);
  if (cells * sizeof(std::uint32_t) > static_cast<long double>(params.max_bytes))
    throw CapacityError(what + " needs " +
                        std::to_string(static_cast<std::uint64_t>(cells) * 4 >> 20) +
                        " MiB, more than the height map's max_bytes of " +
                        std::to_string(params.max_bytes >> 20) + " MiB");
  counts_.assign(static_cast<std::size_t>(cells), 0);
  stats_.bin_counts.assign(bins(), 0);
}

void HeightMap::addFrame(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                         const Eigen::Isometry3d& to_map) {
  // a reflection or a scale is no pose: the points would land mirrored or stretched
  checkRigidTransform(to_map.matrix(), "the frame's pose");
  const Eigen::Matrix3f r = to_map.linear().cast<float>();
  const Eigen::Vector3f t = to_map.translation().cast<float>();
  const auto n = static_cast<std::int64_t>(params_.map_size);
  const double inv = 1.0 / params_.resolution;
  const std::vector<double>& edges = params_.z_bins;
  const std::size_t nb = bins();
  for (const pcl::PointXYZ& p : cloud) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) continue;
    ++stats_.valid_points;
    const Eigen::Vector3f q = r * p.getVector3fMap() + t;
    const std::int64_t col = floorToInt(q.x() * inv) + n / 2;
    const std::int64_t row = n / 2 - 1 - floorToInt(q.y() * inv);
    if (col < 0 || col >= n || row < 0 || row >= n) {
      ++stats_.points_outside_map;
      continue;
    }
    // np.digitize(z, edges): the number of edges <= z.
    const auto bin = static_cast<std::size_t>(
        std::upper_bound(edges.begin(), edges.end(), static_cast<double>(q.z())) - edges.begin());
    ++counts_[(static_cast<std::size_t>(row) * params_.map_size + static_cast<std::size_t>(col)) *
                  nb +
              bin];
    ++stats_.bin_counts[bin];
  }
  ++stats_.frames;
}

bool HeightMap::explored(std::size_t row, std::size_t col) const {
  for (std::size_t b = 0; b < bins(); ++b) {
    if (count(row, col, b) > 0) return true;
  }
  return false;
}

std::size_t HeightMap::obstacleCells() const {
  std::size_t n = 0;
  for (std::size_t r = 0; r < size(); ++r) {
    for (std::size_t c = 0; c < size(); ++c) n += obstacle(r, c) ? 1 : 0;
  }
  return n;
}

std::size_t HeightMap::exploredCells() const {
  std::size_t n = 0;
  for (std::size_t r = 0; r < size(); ++r) {
    for (std::size_t c = 0; c < size(); ++c) n += explored(r, c) ? 1 : 0;
  }
  return n;
}

Eigen::Isometry3d cameraToMap(double height, double pitch_rad, double yaw_rad) {
  for (auto [value, name] :
       {std::pair{height, "height"}, std::pair{pitch_rad, "pitch"}, std::pair{yaw_rad, "yaw"}})
    if (!std::isfinite(value))
      throw std::invalid_argument(std::string("camera pose: ") + name + " is not finite");
  if (std::abs(height) > kMaxTranslation)
    throw std::invalid_argument("camera pose: height beyond 1e6 m");
  // The CLI's --pitch-deg and --yaw-deg bounds (+-90 and +-360 degrees), with a rounding margin
  // for degrees converted to radians.
  constexpr double kHalfPi = M_PI / 2.0, kTwoPi = 2.0 * M_PI, kMargin = 1.0 + 1e-12;
  if (std::abs(pitch_rad) > kHalfPi * kMargin)
    throw std::invalid_argument("camera pose: pitch " + formatNumber(pitch_rad) +
                                " rad is not within [-pi/2, pi/2] (-90 to 90 degrees)");
  if (std::abs(yaw_rad) > kTwoPi * kMargin)
    throw std::invalid_argument("camera pose: yaw " + formatNumber(yaw_rad) +
                                " rad is not within [-2 pi, 2 pi] (-360 to 360 degrees)");
  Eigen::Matrix3d level;  // optical (x right, y down, z forward) -> map (x right, y forward, z up)
  level << 1, 0, 0, 0, 0, 1, 0, -1, 0;
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitZ()).toRotationMatrix() *
               Eigen::AngleAxisd(-pitch_rad, Eigen::Vector3d::UnitX()).toRotationMatrix() * level;
  t.translation() = Eigen::Vector3d(0, 0, height);
  return t;
}

Eigen::Isometry3d cameraToMapFromFloor(const Eigen::Vector3d& n, double d) {
  const Eigen::Vector3d z = n.normalized();
  Eigen::Vector3d y = Eigen::Vector3d::UnitZ() - Eigen::Vector3d::UnitZ().dot(z) * z;
  if (y.norm() < 1e-6)
    throw std::invalid_argument("camera looks straight at the floor: no forward");
  y.normalize();
  const Eigen::Vector3d x = y.cross(z);
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear().row(0) = x.transpose();
  t.linear().row(1) = y.transpose();
  t.linear().row(2) = z.transpose();
  t.translation() = Eigen::Vector3d(0, 0, d / n.norm());
  return t;
}

}  // namespace metricmap
