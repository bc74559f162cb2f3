#pragma once
/// \file cell_table.h
/// \brief Open-addressing hash map from 64-bit cell keys to dense ids (linear probing).

#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace metricmap {

/// \brief Maps each distinct key to the id given when it was first inserted.
/// Not thread-safe; one table per build.
class CellTable {
 public:
  static constexpr std::uint64_t kEmpty = std::numeric_limits<std::uint64_t>::max();

  /// \param[in] expected a hint of how many distinct keys will be inserted
  explicit CellTable(std::size_t expected);

  /// \brief The id of `key`; if absent, stores `new_id` for it and returns it.
  /// \param[in] key any value but kEmpty
  std::size_t findOrInsert(std::uint64_t key, std::size_t new_id);

  std::size_t size() const { return size_; }

  /// \brief All (key, id) pairs, in table order.
  std::vector<std::pair<std::uint64_t, std::size_t>> entries() const;

 private:
  struct Slot {
    std::uint64_t key;
    std::uint64_t id;
  };
  void grow();
  std::size_t slotOf(std::uint64_t key) const {
    return static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> shift_);
  }

  std::vector<Slot> slots_;
  std::size_t size_ = 0;
  int shift_ = 64;
};

}  // namespace metricmap
