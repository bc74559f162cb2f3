#pragma once
/// \file radix_sort.h
/// \brief Stable LSD radix sorts: of packed 64-bit words by a bit field, and of key/value pairs.

#include <cstdint>
#include <vector>

namespace metricmap {

/// \brief Sort `words` ascending by the bit field [low_bit, low_bit + key_bits), stably.
/// Passes use up to 10-bit digits; a pass whose digit never varies is skipped.
/// \param[in,out] scratch reused between calls to avoid fresh allocations (resized as needed)
void radixSortWords(std::vector<std::uint64_t>& words, std::vector<std::uint64_t>& scratch,
                    int low_bit, int key_bits);

/// \brief Sort `keys` ascending and permute `values` alongside; only the low `key_bits` bits
/// of the keys are looked at. Stable.
void radixSortPairs(std::vector<std::uint64_t>& keys, std::vector<std::uint32_t>& values,
                    int key_bits);

/// \brief Number of bits needed to write values 0 .. n-1 (at least 1).
int bitsFor(std::uint64_t n);

}  // namespace metricmap
