#include "metricmap/occupancy/ray_kernel.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>

#include "metricmap/common/fast_floor.h"
#include "metricmap/exceptions.h"
#include "metricmap/occupancy/voxel_key.h"

namespace metricmap::detail {

void BlockHashIndex::clear() {
  std::fill(keys_.begin(), keys_.end(), kEmpty);
  size_ = 0;
}

void BlockHashIndex::grow() {
  const std::size_t capacity = keys_.empty() ? 1024 : keys_.size() * 2;
  std::vector<std::uint64_t> old_keys(capacity, kEmpty);
  std::vector<std::uint32_t> old_values(capacity);
  old_keys.swap(keys_);
  old_values.swap(values_);
  mask_ = capacity - 1;
  shift_ = 64 - __builtin_ctzll(capacity);
  size_ = 0;
  for (std::size_t i = 0; i < old_keys.size(); ++i) {
    if (old_keys[i] == kEmpty) continue;
    std::size_t s = slot(old_keys[i]);
    while (keys_[s] != kEmpty) s = (s + 1) & mask_;
    keys_[s] = old_keys[i];
    values_[s] = old_values[i];
    ++size_;
  }
}

namespace {

/// Marks voxels into the scan's blocks; remembers the last block touched.
class Marker {
 public:
  explicit Marker(ScanUpdate& out) : out_(out) {}

  std::uint64_t* freeWords(std::int64_t bx, std::int64_t by, std::int64_t bz) {
    if (bx != bx_ || by != by_ || bz != bz_) select(bx, by, bz);
    return block_->free;
  }
  void markFree(std::int64_t x, std::int64_t y, std::int64_t z) {
    std::uint64_t* w = freeWords(x >> kBlockShift, y >> kBlockShift, z >> kBlockShift);
    const int i = voxelInBlock(x, y, z);
    w[i >> 6] |= std::uint64_t{1} << (i & 63);
  }
  void markHit(std::int64_t x, std::int64_t y, std::int64_t z) {
    freeWords(x >> kBlockShift, y >> kBlockShift, z >> kBlockShift);
    const int i = voxelInBlock(x, y, z);
    block_->hit[i >> 6] |= std::uint64_t{1} << (i & 63);
  }

 private:
  void select(std::int64_t bx, std::int64_t by, std::int64_t bz) {
    const std::uint64_t key = packVoxelKey(bx, by, bz);
    bool inserted = false;
    const auto next = static_cast<std::uint32_t>(out_.blocks.size());
    const std::uint32_t index = out_.index.findOrInsert(key, next, inserted);
    if (inserted) {
      out_.blocks.emplace_back();
      ScanBlock& b = out_.blocks.back();
      std::memset(b.free, 0, sizeof(b.free));
      std::memset(b.hit, 0, sizeof(b.hit));
      b.key = key;
    }
    block_ = &out_.blocks[index];
    bx_ = bx;
    by_ = by;
    bz_ = bz;
  }

  ScanUpdate& out_;
  ScanBlock* block_ = nullptr;
  std::int64_t bx_ = std::numeric_limits<std::int64_t>::min(), by_ = 0, bz_ = 0;
};

struct Key3 {
  std::int64_t v[3];
};

[[noreturn]] void outsideKeySpace(const float p[3], double resolution) {
  std::ostringstream msg;
  msg << "point (" << p[0] << ", " << p[1] << ", " << p[2] << ") is outside the voxel key space ("
      << "+-" << static_cast<double>(kVoxelKeyLimit) * resolution << " m at resolution "
      << resolution << " m)";
  throw CapacityError(msg.str());
}

/// OctoMap's coordToKey: floor(coordinate * (1 / resolution)) in double.
bool keyOf(const float p[3], double inv_res, Key3& key) {
  for (int i = 0; i < 3; ++i) {
    const double s = inv_res * static_cast<double>(p[i]);
    if (!(s >= -static_cast<double>(kVoxelKeyLimit) && s < static_cast<double>(kVoxelKeyLimit)))
      return false;
    key.v[i] = floorToInt(s);
  }
  return true;
}

/// OctoMap's computeRayKeys (Amanatides & Woo in double from float coordinates): marks every
/// voxel from the origin's up to, not including, the end's.
void walk(const float o[3], const float e[3], const Key3& ko, const Key3& ke, double res,
          Marker& marker) {
  if (ko.v[0] == ke.v[0] && ko.v[1] == ke.v[1] && ko.v[2] == ke.v[2]) return;
  marker.markFree(ko.v[0], ko.v[1], ko.v[2]);
  float dir[3] = {e[0] - o[0], e[1] - o[1], e[2] - o[2]};
  const float length = static_cast<float>(
      std::sqrt(static_cast<double>(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2])));
  dir[0] /= length;
  dir[1] /= length;
  dir[2] /= length;
  int step[3];
  double t_max[3], t_delta[3];
  for (int i = 0; i < 3; ++i) {
    step[i] = dir[i] > 0.0f ? 1 : (dir[i] < 0.0f ? -1 : 0);
    if (step[i] != 0) {
      double border = (static_cast<double>(ko.v[i]) + 0.5) * res;
      border += static_cast<float>(step[i] * res * 0.5);
      t_max[i] = (border - static_cast<double>(o[i])) / static_cast<double>(dir[i]);
      t_delta[i] = res / static_cast<double>(std::fabs(dir[i]));
    } else {
      t_max[i] = std::numeric_limits<double>::max();
      t_delta[i] = std::numeric_limits<double>::max();
    }
  }
  std::int64_t k[3] = {ko.v[0], ko.v[1], ko.v[2]};
  const double len = static_cast<double>(length);
  for (;;) {
    int dim;
    if (t_max[0] < t_max[1])
      dim = t_max[0] < t_max[2] ? 0 : 2;
    else
      dim = t_max[1] < t_max[2] ? 1 : 2;
    k[dim] += step[dim];
    t_max[dim] += t_delta[dim];
    if (k[0] == ke.v[0] && k[1] == ke.v[1] && k[2] == ke.v[2]) return;
    if (std::min(std::min(t_max[0], t_max[1]), t_max[2]) > len) return;
    marker.markFree(k[0], k[1], k[2]);
  }
}

}  // namespace

RayCastCounts castRays(const RayCastInput& in, ScanUpdate& out) {
  out.clear();
  RayCastCounts counts;
  const double res = in.resolution;
  const double inv_res = 1.0 / res;
  const float* o = in.origin;
  Key3 ko;
  if (!keyOf(o, inv_res, ko)) outsideKeySpace(o, res);
  const bool cut_enabled = std::isfinite(in.max_range);
  const auto max_range_f = static_cast<float>(in.max_range);
  Marker marker(out);
  const auto* bytes = reinterpret_cast<const unsigned char*>(in.xyz);
  for (std::size_t n = 0; n < in.count; ++n) {
    const auto* src = reinterpret_cast<const float*>(bytes + n * in.stride_bytes);
    float p[3] = {src[0], src[1], src[2]};
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) {
      ++counts.non_finite;
      continue;
    }
    if (in.pose != nullptr) {
      const float* m = in.pose;
      const float x = p[0], y = p[1], z = p[2];
      p[0] = m[0] * x + m[1] * y + m[2] * z + m[3];
      p[1] = m[4] * x + m[5] * y + m[6] * z + m[7];
      p[2] = m[8] * x + m[9] * y + m[10] * z + m[11];
    }
    ++counts.beams;
    // OctoMap's test: the float difference, its squared norm in float, sqrt in double.
    const float d[3] = {p[0] - o[0], p[1] - o[1], p[2] - o[2]};
    const double norm = std::sqrt(static_cast<double>(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]));
    Key3 ke;
    if (!cut_enabled || norm <= in.max_range) {
      if (!keyOf(p, inv_res, ke)) outsideKeySpace(p, res);
      walk(o, p, ko, ke, res, marker);
      marker.markHit(ke.v[0], ke.v[1], ke.v[2]);
    } else {
      ++counts.cut;
      const auto f = static_cast<float>(norm);
      const float e[3] = {o[0] + (d[0] / f) * max_range_f, o[1] + (d[1] / f) * max_range_f,
                          o[2] + (d[2] / f) * max_range_f};
      if (!keyOf(e, inv_res, ke)) outsideKeySpace(e, res);
      walk(o, e, ko, ke, res, marker);
    }
  }
  return counts;
}

}  // namespace metricmap::detail
