#include "metricmap/common/radix_sort.h"

#include <array>
#include <cstddef>

namespace metricmap {

void radixSortPairs(std::vector<std::uint64_t>& keys, std::vector<std::uint32_t>& values,
                    int key_bits) {
  const std::size_t n = keys.size();
  if (n < 2) return;
  std::vector<std::uint64_t> keys_tmp(n);
  std::vector<std::uint32_t> values_tmp(n);
  for (int shift = 0; shift < key_bits; shift += 8) {
    std::array<std::size_t, 257> offset{};
    for (std::size_t i = 0; i < n; ++i) ++offset[((keys[i] >> shift) & 0xFF) + 1];
    bool single_bucket = false;
    for (int d = 1; d <= 256; ++d) single_bucket = single_bucket || offset[d] == n;
    if (single_bucket) continue;
    for (int d = 1; d <= 256; ++d) offset[d] += offset[d - 1];
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t pos = offset[(keys[i] >> shift) & 0xFF]++;
      keys_tmp[pos] = keys[i];
      values_tmp[pos] = values[i];
    }
    keys.swap(keys_tmp);
    values.swap(values_tmp);
  }
}

}  // namespace metricmap
