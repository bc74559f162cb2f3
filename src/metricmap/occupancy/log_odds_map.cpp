#include "metricmap/occupancy/log_odds_map.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "metricmap/common/memory_budget.h"
#include "metricmap/detail/parallel.h"
#include "metricmap/exceptions.h"
#include "metricmap/occupancy/block_update.h"
#include "metricmap/occupancy/ray_kernel.h"

namespace metricmap {
namespace {

using detail::kBlockShift;
using detail::kBlockVoxels;
using detail::kBlockWords;
using detail::VoxelBlock;

inline float clampLogOdds(float v, float lo, float hi) {
  // OctoMap's updateNodeLogOdds: add, then clamp below, then above.
  if (v < lo) return lo;
  if (v > hi) return hi;
  return v;
}

VoxelKey voxelOf(const VoxelBlock& b, int i) {
  const VoxelKey bk = unpackVoxelKey(b.key);
  constexpr int m = detail::kBlockEdge - 1;
  return {bk.x * detail::kBlockEdge + (i & m), bk.y * detail::kBlockEdge + ((i >> kBlockShift) & m),
          bk.z * detail::kBlockEdge + (i >> (2 * kBlockShift))};
}

}  // namespace

LogOddsMap::LogOddsMap(const LogOddsParams& params) : params_(params) {
  validateLogOddsParams(params_);
  hit_ = logOddsOf(params_.prob_hit);
  miss_ = logOddsOf(params_.prob_miss);
  clamp_min_ = logOddsOf(params_.clamp_min);
  clamp_max_ = logOddsOf(params_.clamp_max);
  threshold_ = logOddsOf(params_.occupancy_threshold);
}

void LogOddsMap::clear() {
  blocks_.clear();
  blocks_.shrink_to_fit();
  index_ = detail::BlockHashIndex();
  known_ = 0;
}

detail::VoxelBlock& LogOddsMap::blockFor(std::uint64_t block_key) {
  bool inserted = false;
  const auto next = static_cast<std::uint32_t>(blocks_.size());
  if (next == detail::BlockHashIndex::kNone) throw CapacityError("log-odds map: too many blocks");
  const std::uint32_t i = index_.findOrInsert(block_key, next, inserted);
  if (inserted) {
    blocks_.emplace_back();
    VoxelBlock& b = blocks_.back();
    std::fill(std::begin(b.log_odds), std::end(b.log_odds), 0.0f);
    std::memset(b.known, 0, sizeof(b.known));
    b.key = block_key;
  }
  return blocks_[i];
}

ScanInsertReport LogOddsMap::insertRaw(const float* xyz, std::size_t stride_bytes,
                                       std::size_t count, const Eigen::Vector3f& sensor_origin,
                                       const float* pose) {
  if (!sensor_origin.allFinite()) {
    std::ostringstream msg;
    msg << "sensor origin must be finite, got (" << sensor_origin.transpose() << ")";
    throw std::invalid_argument(msg.str());
  }
  detail::RayCastInput in;
  in.xyz = xyz;
  in.stride_bytes = stride_bytes;
  in.count = xyz == nullptr ? 0 : count;
  in.pose = pose;
  for (int i = 0; i < 3; ++i) in.origin[i] = sensor_origin[i];
  in.resolution = params_.resolution;
  in.max_range = params_.max_range;
  // Memory budget: each block a scan touches costs its work space (grown by doubling) and, if
  // new, a map block (the block vector also grows by doubling) and hash slots.
  const std::uint64_t budget = memoryBudget();
  std::uint64_t used = memory().reserved_bytes + scratch_.dense.capacity() * 8;
  for (const detail::ScanUpdate& s : thread_scratch_) used += s.dense.capacity() * 8;
  const std::uint64_t per_block =
      2 * sizeof(detail::ScanBlock) + 2 * sizeof(detail::VoxelBlock) + 64;
  in.max_blocks = budget > used ? static_cast<std::size_t>((budget - used) / per_block) : 0;
  // Beams dealt out in turn (thread t casts beams t, t + n, t + 2n, ...): a scan's beams are
  // ordered by laser and angle, and contiguous shares differ in length by half. The shares'
  // marks are sets, united in thread order, so the result does not depend on the dealing.
  const unsigned threads = resolveThreads(threads_, in.count, 8192);
  std::vector<detail::RayCastCounts> shares(threads);
  if (thread_scratch_.size() < threads - 1) thread_scratch_.resize(threads - 1);
  parallelRun(threads, [&](unsigned t) {
    detail::RayCastInput part = in;
    part.xyz = in.xyz == nullptr
                   ? nullptr
                   : reinterpret_cast<const float*>(reinterpret_cast<const unsigned char*>(in.xyz) +
                                                    t * in.stride_bytes);
    part.stride_bytes = in.stride_bytes * threads;
    part.count = in.count > t ? (in.count - t + threads - 1) / threads : 0;
    shares[t] = detail::castRays(part, t == 0 ? scratch_ : thread_scratch_[t - 1]);
  });
  detail::RayCastCounts counts;
  for (unsigned t = 0; t < threads; ++t) {
    if (t > 0)
      detail::uniteScanUpdates(scratch_, thread_scratch_[t - 1], in.max_blocks, in.resolution);
    counts.non_finite += shares[t].non_finite;
    counts.beams += shares[t].beams;
    counts.cut += shares[t].cut;
  }
  ScanInsertReport report;
  report.points = count;
  report.non_finite = counts.non_finite;
  report.beams = counts.beams;
  report.beams_cut = counts.cut;
  applyScan(report);
  return report;
}

void LogOddsMap::applyScan(ScanInsertReport& report) {
  // at most one (geometric) growth per scan
  const std::size_t need = blocks_.size() + scratch_.blocks.size();
  if (need > blocks_.capacity()) blocks_.reserve(std::max(need, 2 * blocks_.capacity()));
  // New blocks join the map in key order: the same order however the beams were shared out.
  const std::size_t count = scratch_.blocks.size();
  order_.resize(count);
  for (std::size_t k = 0; k < count; ++k) order_[k] = static_cast<std::uint32_t>(k);
  std::sort(order_.begin(), order_.end(), [&](std::uint32_t a, std::uint32_t b) {
    return scratch_.blocks[a].key < scratch_.blocks[b].key;
  });
  // Each scan block's map block, found or added here (the only step that changes the map's
  // layout); then the blocks' voxels are updated in shares, each block by one thread.
  targets_.resize(count);
  for (std::size_t k = 0; k < count; ++k) {
    targets_[k] =
        static_cast<std::uint32_t>(&blockFor(scratch_.blocks[order_[k]].key) - blocks_.data());
  }
  // The AVX-512 update where the walk is not forced portable (tests compare the two).
  const bool simd = detail::rayPath() == detail::RayPath::Simd;
  const detail::LogOddsStep step{hit_, miss_, clamp_min_, clamp_max_};
  const unsigned threads = resolveThreads(threads_, count, 256);
  std::vector<detail::BlockUpdateCounts> counts(threads);
  parallelRun(threads, [&](unsigned t) {
    const auto [begin, end] = chunkOf(count, threads, t);
    detail::BlockUpdateCounts c;
    for (std::size_t k = begin; k < end; ++k) {
      detail::updateBlock(scratch_.blocks[order_[k]], blocks_[targets_[k]], step, c, simd);
    }
    counts[t] = c;
  });
  for (const detail::BlockUpdateCounts& c : counts) {
    known_ += c.known;
    report.hit_voxels += c.hits;
    report.miss_voxels += c.misses;
  }
}

void LogOddsMap::merge(const LogOddsMap& other) {
  const LogOddsParams& a = params_;
  const LogOddsParams& b = other.params_;
  if (a.resolution != b.resolution || a.prob_hit != b.prob_hit || a.prob_miss != b.prob_miss ||
      a.clamp_min != b.clamp_min || a.clamp_max != b.clamp_max ||
      a.occupancy_threshold != b.occupancy_threshold) {
    std::ostringstream msg;
    msg << "merge: maps differ in resolution or sensor model (resolution " << a.resolution << " vs "
        << b.resolution << ")";
    throw std::invalid_argument(msg.str());
  }
  if (&other == this) throw std::invalid_argument("merge: a map cannot be merged with itself");
  for (const VoxelBlock& ob : other.blocks_) {
    mergeInto(blockFor(ob.key), ob.known, [&ob](int index) { return ob.log_odds[index]; });
  }
}

void LogOddsMap::forEachBlock(
    const std::function<void(std::uint64_t, const std::uint64_t*, const float*)>& visit) const {
  for (const VoxelBlock& b : blocks_) visit(b.key, b.known, b.log_odds);
}

void LogOddsMap::mergeBlock(std::uint64_t block_key, const std::uint64_t* known,
                            const float* values) {
  mergeInto(blockFor(block_key), known, [&values](int) { return *values++; });
}

template <typename NextValue>
void LogOddsMap::mergeInto(VoxelBlock& blk, const std::uint64_t* known, NextValue value_of) {
  for (int w = 0; w < kBlockWords; ++w) {
    std::uint64_t bits = known[w];
    known_ += static_cast<std::size_t>(__builtin_popcountll(bits & ~blk.known[w]));
    const std::uint64_t unknown = ~blk.known[w];
    blk.known[w] |= bits;
    while (bits != 0) {  // voxels in ascending index order
      const int i = __builtin_ctzll(bits);
      bits &= bits - 1;
      float& v = blk.log_odds[w * 64 + i];
      const float add = value_of(w * 64 + i);
      v = (unknown >> i) & 1 ? add : clampLogOdds(v + add, clamp_min_, clamp_max_);
    }
  }
}

void LogOddsMap::setLogOdds(const VoxelKey& key, float log_odds) {
  if (!inKeySpace(key)) {
    std::ostringstream msg;
    msg << "voxel (" << key.x << ", " << key.y << ", " << key.z << ") is outside the key space";
    throw CapacityError(msg.str());
  }
  if (!std::isfinite(log_odds)) throw std::invalid_argument("log-odds must be finite");
  VoxelBlock& b =
      blockFor(packVoxelKey(key.x >> kBlockShift, key.y >> kBlockShift, key.z >> kBlockShift));
  const int i = detail::voxelInBlock(key.x, key.y, key.z);
  const std::uint64_t bit = std::uint64_t{1} << (i & 63);
  if ((b.known[i >> 6] & bit) == 0) ++known_;
  b.known[i >> 6] |= bit;
  b.log_odds[i] = log_odds;
}

VoxelKey LogOddsMap::keyOf(const Eigen::Vector3d& p) const {
  const double inv = 1.0 / params_.resolution;
  return {static_cast<std::int64_t>(std::floor(inv * p.x())),
          static_cast<std::int64_t>(std::floor(inv * p.y())),
          static_cast<std::int64_t>(std::floor(inv * p.z()))};
}

Eigen::Vector3d LogOddsMap::centerOf(const VoxelKey& key) const {
  const double r = params_.resolution;
  return {(static_cast<double>(key.x) + 0.5) * r, (static_cast<double>(key.y) + 0.5) * r,
          (static_cast<double>(key.z) + 0.5) * r};
}

std::optional<float> LogOddsMap::logOdds(const VoxelKey& key) const {
  if (!inKeySpace(key)) return std::nullopt;
  const std::uint32_t bi =
      index_.find(packVoxelKey(key.x >> kBlockShift, key.y >> kBlockShift, key.z >> kBlockShift));
  if (bi == detail::BlockHashIndex::kNone) return std::nullopt;
  const VoxelBlock& b = blocks_[bi];
  const int i = detail::voxelInBlock(key.x, key.y, key.z);
  if (((b.known[i >> 6] >> (i & 63)) & 1) == 0) return std::nullopt;
  return b.log_odds[i];
}

VoxelState LogOddsMap::state(const VoxelKey& key) const {
  const std::optional<float> l = logOdds(key);
  if (!l) return VoxelState::Unknown;
  return isOccupied(*l) ? VoxelState::Occupied : VoxelState::Free;
}

double LogOddsMap::probability(const VoxelKey& key) const {
  const std::optional<float> l = logOdds(key);
  return l ? probabilityOf(*l) : 0.5;
}

void LogOddsMap::forEachKnown(const std::function<void(const VoxelKey&, float)>& visit) const {
  for (const VoxelBlock& b : blocks_) {
    for (int w = 0; w < kBlockWords; ++w) {
      for (std::uint64_t bits = b.known[w]; bits != 0; bits &= bits - 1) {
        const int i = w * 64 + __builtin_ctzll(bits);
        visit(voxelOf(b, i), b.log_odds[i]);
      }
    }
  }
}

std::size_t LogOddsMap::occupiedVoxels() const {
  std::size_t n = 0;
  for (const VoxelBlock& b : blocks_) {
    for (int w = 0; w < kBlockWords; ++w) {
      for (std::uint64_t bits = b.known[w]; bits != 0; bits &= bits - 1) {
        n += isOccupied(b.log_odds[w * 64 + __builtin_ctzll(bits)]) ? 1 : 0;
      }
    }
  }
  return n;
}

bool LogOddsMap::keyBounds(VoxelKey& min_key, VoxelKey& max_key) const {
  if (known_ == 0) return false;
  constexpr auto big = std::numeric_limits<std::int64_t>::max();
  min_key = {big, big, big};
  max_key = {-big, -big, -big};
  forEachKnown([&](const VoxelKey& k, float) {
    min_key = {std::min(min_key.x, k.x), std::min(min_key.y, k.y), std::min(min_key.z, k.z)};
    max_key = {std::max(max_key.x, k.x), std::max(max_key.y, k.y), std::max(max_key.z, k.z)};
  });
  return true;
}

LogOddsMemory LogOddsMap::memory() const {
  LogOddsMemory m;
  m.blocks = blocks_.size();
  m.known_voxels = known_;
  m.bytes = blocks_.size() * sizeof(VoxelBlock) + index_.bytes();
  m.reserved_bytes = blocks_.capacity() * sizeof(VoxelBlock) + index_.bytes();
  m.bytes_per_known_voxel =
      known_ == 0 ? 0.0 : static_cast<double>(m.bytes) / static_cast<double>(known_);
  return m;
}

}  // namespace metricmap
