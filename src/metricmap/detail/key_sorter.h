#pragma once
/// \file key_sorter.h
/// \brief Collects (cell key, point position) pairs and sorts them by key with a radix sort.
///
/// When key and position fit together in 64 bits they are packed into one word (one array to
/// sort, half the memory traffic); otherwise keys and positions are sorted as pairs.

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#include "metricmap/detail/huge_pages.h"
#include "metricmap/detail/radix_sort.h"

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

  /// \brief Writes packed words into one chunk's region (fillParallel).
  class Sink {
   public:
    Sink(std::uint64_t* out, int position_bits) : out_(out), position_bits_(position_bits) {}
    void push(std::uint64_t key, std::uint32_t position) {
      *out_++ = key << position_bits_ | position;
    }
    std::uint64_t* end() const { return out_; }

   private:
    std::uint64_t* out_;
    int position_bits_;
  };

  /// \brief Push the keys of items [0, n) in `threads` contiguous chunks at once:
  /// `fill(begin, end, sink)` pushes the keys of items [begin, end) in increasing position
  /// order through `sink.push(key, position)`. The result is the same as one fill over [0, n)
  /// (chunks are joined in order). Call after reset(n, ...).
  template <typename Fill>
  void fillParallel(std::size_t n, unsigned threads, Fill&& fill) {
    if (threads <= 1 || !packed_) {
      fill(std::size_t{0}, n, *this);
      return;
    }
    words_.resize(n);  // uninitialised: each thread touches its own pages
    std::vector<std::size_t> filled(threads);
    parallelRun(threads, [&](unsigned t) {
      const auto [begin, end] = chunkOf(n, threads, t);
      Sink sink(words_.data() + begin, position_bits_);
      fill(begin, end, sink);
      filled[t] = static_cast<std::size_t>(sink.end() - (words_.data() + begin));
    });
    std::size_t total = filled[0];  // close the gaps left by skipped items, in chunk order
    for (unsigned t = 1; t < threads; ++t) {
      const std::size_t begin = chunkOf(n, threads, t).first;
      if (total != begin && filled[t] > 0) {
        std::memmove(words_.data() + total, words_.data() + begin,
                     filled[t] * sizeof(std::uint64_t));
      }
      total += filled[t];
    }
    words_.resize(total);
  }

  /// \brief Sort by key; equal keys keep their push order. Any thread count gives the same
  /// order.
  void sort(unsigned threads = 1) {
    if (packed_) {
      radixSortWords(words_, scratch_, position_bits_, key_bits_, threads);
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
  SortWords words_;
  std::vector<std::uint64_t> keys_;
  std::vector<std::uint32_t> positions_;
  SortWords scratch_;
};

}  // namespace metricmap
