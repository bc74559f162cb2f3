#include "metricmap/detail/radix_sort.h"

#include <algorithm>
#include <cstddef>

#include "metricmap/detail/huge_pages.h"

namespace metricmap {
namespace {

struct Plan {
  int passes = 0;
  int digit_bits = 0;
};

Plan plan(int key_bits) {
  Plan p;
  if (key_bits <= 0) return p;
  p.passes = (key_bits + 9) / 10;  // 10-bit digits measured fastest here (docs/BENCHMARKS.md)
  p.digit_bits = (key_bits + p.passes - 1) / p.passes;
  return p;
}

}  // namespace

int bitsFor(std::uint64_t n) {
  int bits = 1;
  while (bits < 64 && (std::uint64_t{1} << bits) < n) ++bits;
  return bits;
}

namespace {

void serialSortWords(SortWords& words, SortWords& scratch, int low_bit, const Plan& p) {
  const std::size_t n = words.size();
  const std::size_t buckets = std::size_t{1} << p.digit_bits;
  const std::uint64_t mask = buckets - 1;
  // All histograms in one read pass.
  std::vector<std::size_t> hist(buckets * static_cast<std::size_t>(p.passes), 0);
  for (const std::uint64_t w : words) {
    for (int k = 0; k < p.passes; ++k)
      ++hist[k * buckets + ((w >> (low_bit + k * p.digit_bits)) & mask)];
  }
  reserveHuge(scratch, n);
  scratch.resize(n);
  for (int k = 0; k < p.passes; ++k) {
    std::size_t* h = &hist[k * buckets];
    if (std::any_of(h, h + buckets, [n](std::size_t c) { return c == n; })) continue;
    std::size_t sum = 0;
    for (std::size_t b = 0; b < buckets; ++b) {
      const std::size_t c = h[b];
      h[b] = sum;
      sum += c;
    }
    const int shift = low_bit + k * p.digit_bits;
    for (const std::uint64_t w : words) scratch[h[(w >> shift) & mask]++] = w;
    words.swap(scratch);
  }
}

/// Per pass: every thread counts its chunk, offsets are laid out digit by digit and within a
/// digit chunk by chunk (stable), then every thread scatters its chunk.
void parallelSortWords(SortWords& words, SortWords& scratch, int low_bit, const Plan& p,
                       unsigned threads) {
  const std::size_t n = words.size();
  const std::size_t buckets = std::size_t{1} << p.digit_bits;
  const std::uint64_t mask = buckets - 1;
  reserveHuge(scratch, n);
  scratch.resize(n);
  std::vector<std::size_t> hist(buckets * threads);
  for (int k = 0; k < p.passes; ++k) {
    const int shift = low_bit + k * p.digit_bits;
    parallelRun(threads, [&](unsigned t) {
      std::size_t* h = &hist[t * buckets];
      std::fill(h, h + buckets, 0);
      const auto [begin, end] = chunkOf(n, threads, t);
      for (std::size_t i = begin; i < end; ++i) ++h[(words[i] >> shift) & mask];
    });
    bool trivial = false;
    std::size_t sum = 0;
    for (std::size_t b = 0; b < buckets; ++b) {
      std::size_t digit_total = 0;
      for (unsigned t = 0; t < threads; ++t) {
        const std::size_t c = hist[t * buckets + b];
        hist[t * buckets + b] = sum;
        sum += c;
        digit_total += c;
      }
      trivial = trivial || digit_total == n;
    }
    if (trivial) continue;  // every word has the same digit: the order stays
    parallelRun(threads, [&](unsigned t) {
      std::size_t* h = &hist[t * buckets];
      const auto [begin, end] = chunkOf(n, threads, t);
      for (std::size_t i = begin; i < end; ++i) {
        const std::uint64_t w = words[i];
        scratch[h[(w >> shift) & mask]++] = w;
      }
    });
    words.swap(scratch);
  }
}

}  // namespace

void radixSortWords(SortWords& words, SortWords& scratch, int low_bit, int key_bits,
                    unsigned threads) {
  const Plan p = plan(key_bits);
  if (words.size() < 2 || p.passes == 0) return;
  if (threads <= 1) {
    serialSortWords(words, scratch, low_bit, p);
  } else {
    parallelSortWords(words, scratch, low_bit, p, threads);
  }
}

void radixSortPairs(std::vector<std::uint64_t>& keys, std::vector<std::uint32_t>& values,
                    int key_bits) {
  const std::size_t n = keys.size();
  const Plan p = plan(key_bits);
  if (n < 2 || p.passes == 0) return;
  const std::size_t buckets = std::size_t{1} << p.digit_bits;
  const std::uint64_t mask = buckets - 1;
  std::vector<std::uint64_t> keys_tmp(n);
  std::vector<std::uint32_t> values_tmp(n);
  std::vector<std::size_t> h(buckets);
  for (int k = 0; k < p.passes; ++k) {
    const int shift = k * p.digit_bits;
    std::fill(h.begin(), h.end(), 0);
    for (const std::uint64_t key : keys) ++h[(key >> shift) & mask];
    if (std::any_of(h.begin(), h.end(), [n](std::size_t c) { return c == n; })) continue;
    std::size_t sum = 0;
    for (std::size_t& c : h) {
      const std::size_t count = c;
      c = sum;
      sum += count;
    }
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t pos = h[(keys[i] >> shift) & mask]++;
      keys_tmp[pos] = keys[i];
      values_tmp[pos] = values[i];
    }
    keys.swap(keys_tmp);
    values.swap(values_tmp);
  }
}

}  // namespace metricmap
