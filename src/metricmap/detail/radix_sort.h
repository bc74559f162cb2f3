#pragma once
/// \file radix_sort.h
/// \brief Stable LSD radix sorts: of packed 64-bit words by a bit field, and of key/value pairs.

#include <cstdint>
#include <vector>

#include "metricmap/detail/parallel.h"

namespace metricmap {

/// \brief Words to sort: resize() leaves new words uninitialised.
using SortWords = std::vector<std::uint64_t, UninitAllocator<std::uint64_t>>;

/// \brief Sort `words` ascending by the bit field [low_bit, low_bit + key_bits), stably.
/// Passes use up to 10-bit digits; a pass whose digit never varies is skipped. With
/// `threads` > 1 each pass counts and scatters contiguous chunks in parallel (chunk t's words
/// go before chunk t+1's within a digit, so the result is the same for any thread count).
/// \param[in,out] scratch reused between calls to avoid fresh allocations (resized as needed)
void radixSortWords(SortWords& words, SortWords& scratch, int low_bit, int key_bits,
                    unsigned threads = 1);

/// \brief Sort `keys` ascending and permute `values` alongside; only the low `key_bits` bits
/// of the keys are looked at. Stable.
void radixSortPairs(std::vector<std::uint64_t>& keys, std::vector<std::uint32_t>& values,
                    int key_bits);

/// \brief Number of bits needed to write values 0 .. n-1 (at least 1).
int bitsFor(std::uint64_t n);

}  // namespace metricmap
