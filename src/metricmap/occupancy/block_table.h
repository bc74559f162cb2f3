#pragma once
/// \file block_table.h
/// \brief Internals of LogOddsMap: voxels in blocks of 8^3 found through an open-addressing
/// hash of packed block keys. Not part of the stable interface.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace metricmap::detail {

/// \brief Voxels per block edge (log2) and per block.
constexpr int kBlockShift = 3;
constexpr int kBlockEdge = 1 << kBlockShift;
constexpr int kBlockVoxels = kBlockEdge * kBlockEdge * kBlockEdge;
constexpr int kBlockWords = kBlockVoxels / 64;

/// \brief Index of voxel (x, y, z) inside its block: x fastest.
inline int voxelInBlock(std::int64_t x, std::int64_t y, std::int64_t z) {
  constexpr std::int64_t m = kBlockEdge - 1;
  return static_cast<int>(((z & m) << (2 * kBlockShift)) | ((y & m) << kBlockShift) | (x & m));
}

/// \brief 8^3 log-odds and a bit per voxel saying whether it was ever observed.
struct VoxelBlock {
  float log_odds[kBlockVoxels];
  std::uint64_t known[kBlockWords];
  std::uint64_t key;  ///< packVoxelKey of the block coordinates (voxel key >> 3)
};

/// \brief Open-addressing map from a packed key (never ~0) to a 32-bit index.
class BlockHashIndex {
 public:
  static constexpr std::uint32_t kNone = 0xffffffffu;

  /// \brief The index stored for `key`, or kNone.
  std::uint32_t find(std::uint64_t key) const {
    if (keys_.empty()) return kNone;
    for (std::size_t s = slot(key);; s = (s + 1) & mask_) {
      if (keys_[s] == key) return values_[s];
      if (keys_[s] == kEmpty) return kNone;
    }
  }
  /// \brief The index stored for `key`; stores `value` first when the key is new.
  std::uint32_t findOrInsert(std::uint64_t key, std::uint32_t value, bool& inserted) {
    if ((size_ + 1) * 2 > keys_.size()) grow();
    for (std::size_t s = slot(key);; s = (s + 1) & mask_) {
      if (keys_[s] == key) {
        inserted = false;
        return values_[s];
      }
      if (keys_[s] == kEmpty) {
        keys_[s] = key;
        values_[s] = value;
        ++size_;
        inserted = true;
        return value;
      }
    }
  }
  /// \brief Forget every key, keep the capacity.
  void clear();
  std::size_t size() const { return size_; }
  /// \brief Heap bytes held.
  std::size_t bytes() const { return keys_.capacity() * 8 + values_.capacity() * 4; }

 private:
  static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};
  std::size_t slot(std::uint64_t key) const {
    return static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> shift_) & mask_;
  }
  void grow();

  std::vector<std::uint64_t> keys_;
  std::vector<std::uint32_t> values_;
  std::size_t size_ = 0, mask_ = 0;
  int shift_ = 64;
};

/// \brief One scan's updates of a block: voxels crossed by a beam, voxels holding an endpoint.
struct ScanBlock {
  std::uint64_t free[kBlockWords];
  std::uint64_t hit[kBlockWords];
  std::uint64_t key;
};

/// \brief The per-scan work space: touched blocks, found through their own hash.
struct ScanUpdate {
  std::vector<ScanBlock> blocks;
  BlockHashIndex index;
  /// Dense free/hit bits over the scan's bounding box, 16 words per block (kept zeroed).
  std::vector<std::uint64_t> dense;
  /// Beam ends of the scan: float end point, key, hit flag.
  struct End {
    float e[3];
    std::int32_t k[3];
    std::int32_t hit;
  };
  std::vector<End> ends;
  void clear() {
    blocks.clear();
    index.clear();
  }
};

}  // namespace metricmap::detail
