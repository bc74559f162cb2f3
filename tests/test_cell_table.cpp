// CellTable and radixSortPairs against std::map and std::stable_sort.
#include <algorithm>
#include <map>
#include <random>

#include <gtest/gtest.h>

#include "metricmap/common/cell_table.h"
#include "metricmap/common/radix_sort.h"

namespace metricmap {

TEST(CellTable, AgreesWithStdMapThroughGrowth) {
  std::mt19937_64 rng(7);
  CellTable table(4);
  std::map<std::uint64_t, std::size_t> reference;
  for (int i = 0; i < 20000; ++i) {
    const std::uint64_t key = rng() % 5000 * 0x10001ull;  // many repeats, spread bits
    const std::size_t id = table.findOrInsert(key, reference.size());
    auto [it, inserted] = reference.emplace(key, reference.size());
    ASSERT_EQ(id, it->second);
  }
  EXPECT_EQ(table.size(), reference.size());
  auto entries = table.entries();
  std::sort(entries.begin(), entries.end());
  ASSERT_EQ(entries.size(), reference.size());
  std::size_t k = 0;
  for (const auto& [key, id] : reference) {
    EXPECT_EQ(entries[k].first, key);
    EXPECT_EQ(entries[k].second, id);
    ++k;
  }
}

TEST(RadixSort, MatchesStableSortForEveryKeyWidth) {
  std::mt19937_64 rng(11);
  for (int bits : {1, 7, 8, 9, 30, 63, 64}) {
    std::vector<std::uint64_t> keys(5000);
    std::vector<std::uint32_t> values(keys.size());
    const std::uint64_t mask = bits == 64 ? ~0ull : ((1ull << bits) - 1);
    for (std::size_t i = 0; i < keys.size(); ++i) {
      keys[i] = rng() & mask;
      values[i] = static_cast<std::uint32_t>(i);
    }
    std::vector<std::pair<std::uint64_t, std::uint32_t>> ref;
    for (std::size_t i = 0; i < keys.size(); ++i) ref.emplace_back(keys[i], values[i]);
    std::stable_sort(ref.begin(), ref.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    radixSortPairs(keys, values, bits);
    for (std::size_t i = 0; i < keys.size(); ++i) {
      ASSERT_EQ(keys[i], ref[i].first) << "bits " << bits;
      ASSERT_EQ(values[i], ref[i].second) << "bits " << bits;
    }
  }
}

}  // namespace metricmap
