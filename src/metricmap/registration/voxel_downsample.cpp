#include "metricmap/registration/voxel_downsample.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "metricmap/detail/voxel_key.h"

namespace metricmap {
namespace {

// An open-addressing set of packed voxel keys (linear probing; ~0 marks an empty slot, which
// no packed key equals). Its table is kept per thread and reused, so that a scan's
// downsampling does not touch fresh pages.
class KeySet {
 public:
  explicit KeySet(std::size_t expected) : table_(storage()) {
    std::size_t cap = 1024;
    while (cap < 2 * expected) cap *= 2;
    reset(cap);
  }
  /// True when `key` was not in the set yet.
  bool insert(std::uint64_t key) {
    if (2 * (size_ + 1) > table_.size()) grow();
    return place(key);
  }

 private:
  static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};
  static std::vector<std::uint64_t>& storage() {
    thread_local std::vector<std::uint64_t> t;
    return t;
  }
  void reset(std::size_t cap) {
    table_.assign(cap, kEmpty);
    mask_ = cap - 1;
    shift_ = fibonacciShift(cap);
    size_ = 0;
  }
  bool place(std::uint64_t key) {
    for (std::size_t i = fibonacciSlot(key, shift_);; i = (i + 1) & mask_) {
      if (table_[i] == key) return false;
      if (table_[i] == kEmpty) {
        table_[i] = key;
        ++size_;
        return true;
      }
    }
  }
  void grow() {
    std::vector<std::uint64_t> old;
    old.swap(table_);
    reset(old.size() * 2);
    for (const std::uint64_t k : old) {
      if (k != kEmpty) place(k);
    }
  }
  std::vector<std::uint64_t>& table_;
  std::size_t mask_ = 0, size_ = 0;
  int shift_ = 64;
};

void checkVoxel(double voxel) {
  if (!(std::isfinite(voxel) && voxel > 0.0)) {
    throw std::invalid_argument("voxel size must be a finite number > 0, got " +
                                std::to_string(voxel));
  }
}

// The first point per cell of the points for which `take(p)` holds. Consecutive points of a
// scan mostly share a cell, so a point in the cell of the last one taken skips the set.
template <class Get, class Take>
void firstPerCell(std::size_t n, Get get, double voxel, Take take, Points3d& out,
                  std::vector<int>* kept) {
  checkVoxel(voxel);
  const double inv = 1.0 / voxel;
  KeySet seen(n / 4 + 16);
  out.clear();
  out.reserve(n / 4 + 16);
  if (kept) kept->clear();
  std::uint64_t last = ~std::uint64_t{0};  // no packed key equals it
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d p = get(i);
    if (!take(p)) continue;
    const Eigen::Array3i c = voxelOf(p, inv);
    const std::uint64_t key = packVoxelKey(c.x(), c.y(), c.z());
    if (key == last) continue;
    last = key;
    if (seen.insert(key)) {
      out.push_back(p);
      if (kept) kept->push_back(static_cast<int>(i));
    }
  }
}

template <class Get>
RangeWindowCounts windowed(std::size_t n, Get get, double min_range, double max_range, double voxel,
                           Points3d& out, std::vector<int>* kept) {
  RangeWindowCounts counts;
  const double r_min2 = min_range * min_range, r_max2 = max_range * max_range;
  firstPerCell(
      n, get, voxel,
      [&](const Eigen::Vector3d& p) {
        if (!p.allFinite()) return false;
        ++counts.finite;
        const double r2 = p.squaredNorm();
        if (r2 < r_min2 || r2 > r_max2) return false;
        ++counts.in_range;
        return true;
      },
      out, kept);
  return counts;
}

}  // namespace

void voxelDownsample(const Points3d& points, double voxel, Points3d& out, std::vector<int>* kept) {
  if (&out == &points) throw std::invalid_argument("voxelDownsample: output aliases the input");
  firstPerCell(
      points.size(), [&](std::size_t i) { return points[i]; }, voxel,
      [](const Eigen::Vector3d&) { return true; }, out, kept);
}

Points3d voxelDownsample(const Points3d& points, double voxel, std::vector<int>* kept) {
  Points3d out;
  voxelDownsample(points, voxel, out, kept);
  return out;
}

RangeWindowCounts downsampleInRange(const Points3d& points, double min_range, double max_range,
                                    double voxel, Points3d& out, std::vector<int>* kept) {
  return windowed(
      points.size(), [&](std::size_t i) { return points[i]; }, min_range, max_range, voxel, out,
      kept);
}

RangeWindowCounts downsampleInRange(const pcl::PointCloud<pcl::PointXYZ>& points, double min_range,
                                    double max_range, double voxel, Points3d& out,
                                    std::vector<int>* kept) {
  return windowed(
      points.size(),
      [&](std::size_t i) -> Eigen::Vector3d { return points[i].getVector3fMap().cast<double>(); },
      min_range, max_range, voxel, out, kept);
}

}  // namespace metricmap
