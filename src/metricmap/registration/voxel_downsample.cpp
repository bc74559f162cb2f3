#include "metricmap/registration/voxel_downsample.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "metricmap/registration/voxel_key.h"

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
    shift_ = 64;
    for (std::size_t c = cap; c > 1; c >>= 1) --shift_;
    size_ = 0;
  }
  bool place(std::uint64_t key) {
    // Fibonacci hashing: the product's top bits depend on every bit of the key.
    for (std::size_t i = (key * 0x9E3779B97F4A7C15ull) >> shift_;; i = (i + 1) & mask_) {
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

}  // namespace

Points3d voxelDownsample(const Points3d& points, double voxel, std::vector<int>* kept) {
  if (!(std::isfinite(voxel) && voxel > 0.0)) {
    throw std::invalid_argument("voxel size must be a finite number > 0, got " +
                                std::to_string(voxel));
  }
  const double inv = 1.0 / voxel;
  KeySet seen(points.size() / 4 + 16);
  Points3d out;
  out.reserve(points.size() / 4 + 16);
  if (kept) kept->clear();
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Array3i c = voxelOf(points[i], inv);
    if (seen.insert(packVoxel(c.x(), c.y(), c.z()))) {
      out.push_back(points[i]);
      if (kept) kept->push_back(static_cast<int>(i));
    }
  }
  return out;
}

}  // namespace metricmap
