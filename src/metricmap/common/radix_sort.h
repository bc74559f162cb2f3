#pragma once
/// \file radix_sort.h
/// \brief LSD radix sort of (64-bit key, 32-bit value) pairs by key, stable.

#include <cstdint>
#include <vector>

namespace metricmap {

/// \brief Sort `keys` ascending and permute `values` alongside; only the low `key_bits` bits
/// of the keys are looked at (8 bits per pass; passes whose digit never varies are skipped).
void radixSortPairs(std::vector<std::uint64_t>& keys, std::vector<std::uint32_t>& values,
                    int key_bits);

}  // namespace metricmap
