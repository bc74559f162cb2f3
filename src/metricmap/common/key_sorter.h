#pragma once
/// \file key_sorter.h
/// \brief Collects (cell key, point position) pairs and sorts them by key with a radix sort.
///
/// When key and position fit together in 64 bits they are packed into one word (one array to
/// sort, half the memory traffic); otherwise keys and positions are sorted as pairs.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "metricmap/common/huge_pages.h"
#include "metricmap/common/radix_sort.h"

namespace metricmap {

class KeySorter {
 public:
  KeySorter() = default;

  /// \brief Start a new batch; buffers keep their capacity between batches.
  /// \param[in] max_points upper bound on push() calls (< 2^32)
  /// \param[in] key_bits keys are < 2^key_bits
  void reset(std::size_t max_points, int key_bits) {
    key_bits_ = key_bits;
    position_bits_ = bitsFor(max_points);
    packed_ = key_bits_ + position_bits_ <= 64;
    words_.clear();
    keys_.clear();
    positions_.clear();
    if (packed_) {
      reserveHuge(words_, max_points);
    } else {
      reserveHuge(keys_, max_points);
      reserveHuge(positions_, max_points);
    }
  }

  /// \brief Add a point; positions must be pushed in increasing order for a stable result.
  void push(std::uint64_t key, std::uint32_t position) {
    if (packed_) {
      words_.push_back(key << position_bits_ | position);
    } else {
      keys_.push_back(key);
      positions_.push_back(position);
    }
  }

  /// \brief Sort by key; equal keys keep their push order.
  void sort() {
    if (packed_) {
      radixSortWords(words_, scratch_, position_bits_, key_bits_);
    } else {
      radixSortPairs(keys_, positions_, key_bits_);
    }
  }

  std::size_t size() const { return packed_ ? words_.size() : keys_.size(); }
  std::uint64_t key(std::size_t i) const {
    return packed_ ? words_[i] >> position_bits_ : keys_[i];
  }
  std::uint32_t position(std::size_t i) const {
    return packed_
               ? static_cast<std::uint32_t>(words_[i] & ((std::uint64_t{1} << position_bits_) - 1))
               : positions_[i];
  }

 private:
  int key_bits_ = 0;
  int position_bits_ = 1;
  bool packed_ = false;
  std::vector<std::uint64_t> words_;
  std::vector<std::uint64_t> keys_;
  std::vector<std::uint32_t> positions_;
  std::vector<std::uint64_t> scratch_;
};

}  // namespace metricmap
