// The floor of a sort-based exact grid build on this machine: the same cloud and cell size as
// BM_OccupancyGrid, with only the memory traffic no such build can avoid (one bounds pass, one
// key pass, a 3-pass LSD radix sort of packed 64-bit words, the gather of the points in key
// order, one 64-byte record per cell). No NaN checks, no statistics, no capacity checks: a
// lower bound to compare the 5x target against (docs/BENCHMARKS.md), not a usable filter.
#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "bench_common.h"
#include "metricmap/detail/fast_floor.h"

namespace metricmap::bench {
namespace {

struct Record {  // what an exact build must emit per cell: index, count, mean, first point
  std::int64_t index[3];
  std::uint64_t count;
  double mean[3];
  std::uint64_t first;
};

void BM_SortBasedGridFloor(benchmark::State& state) {
  const auto cloud = kittiCloud();
  const std::size_t n = cloud->size();
  const float inv = 1.0f / 0.1f;
  std::vector<std::uint64_t> words(n), scratch(n);
  std::vector<Record> cells(n);
  std::size_t occupied = 0;
  for (auto _ : state) {
    float lo[3] = {1e30f, 1e30f, 1e30f}, hi[3] = {-1e30f, -1e30f, -1e30f};
    for (const auto& p : *cloud) {
      for (int a = 0; a < 3; ++a) {
        lo[a] = std::min(lo[a], p.data[a]);
        hi[a] = std::max(hi[a], p.data[a]);
      }
    }
    std::int64_t base[3], dims[3];
    for (int a = 0; a < 3; ++a) {
      base[a] = floorToInt(lo[a] * inv);
      dims[a] = floorToInt(hi[a] * inv) - base[a] + 1;
    }
    constexpr int kPositionBits = 22, kDigit = 10, kPasses = 3;
    static_assert(kPositionBits + kDigit * kPasses <= 64, "packed word");
    if (n > (std::size_t{1} << kPositionBits) || dims[0] * dims[1] * dims[2] > (1ll << 30)) {
      state.SkipWithError("cloud too large for the fixed 22 + 30 bit words");
      break;
    }
    for (std::size_t i = 0; i < n; ++i) {
      const float* p = (*cloud)[i].data;
      const auto k =
          static_cast<std::uint64_t>((floorToInt(p[0] * inv) - base[0]) +
                                     dims[0] * ((floorToInt(p[1] * inv) - base[1]) +
                                                dims[1] * (floorToInt(p[2] * inv) - base[2])));
      words[i] = k << kPositionBits | i;
    }
    for (int pass = 0; pass < kPasses; ++pass) {
      const int shift = kPositionBits + pass * kDigit;
      std::array<std::size_t, 1 << kDigit> h{};
      for (const std::uint64_t w : words) ++h[(w >> shift) & ((1 << kDigit) - 1)];
      std::size_t sum = 0;
      for (auto& c : h) sum += std::exchange(c, sum);
      for (const std::uint64_t w : words) scratch[h[(w >> shift) & ((1 << kDigit) - 1)]++] = w;
      words.swap(scratch);
    }
    occupied = 0;
    constexpr std::uint64_t kPos = (std::uint64_t{1} << kPositionBits) - 1;
    for (std::size_t b = 0; b < n;) {
      const std::uint64_t key = words[b] >> kPositionBits;
      double s[3] = {0, 0, 0};
      std::size_t e = b;
      for (; e < n && words[e] >> kPositionBits == key; ++e) {
        if (e + 48 < n) __builtin_prefetch(&(*cloud)[words[e + 48] & kPos]);
        const float* p = (*cloud)[words[e] & kPos].data;
        s[0] += p[0];
        s[1] += p[1];
        s[2] += p[2];
      }
      Record& r = cells[occupied++];
      const auto k = static_cast<std::int64_t>(key);
      r.index[0] = k % dims[0];
      r.index[1] = k / dims[0] % dims[1];
      r.index[2] = k / (dims[0] * dims[1]);
      r.count = e - b;
      for (int a = 0; a < 3; ++a) r.mean[a] = s[a] / static_cast<double>(r.count);
      r.first = words[b] & kPos;
      b = e;
    }
    benchmark::DoNotOptimize(cells.data());
  }
  state.counters["cells"] = static_cast<double>(occupied);
  report(state, n, 0.0);
}

BENCHMARK(BM_SortBasedGridFloor)->Unit(benchmark::kMillisecond)->MinTime(2.0);

}  // namespace
}  // namespace metricmap::bench
