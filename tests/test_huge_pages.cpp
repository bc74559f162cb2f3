// adviseHugePages / reserveHuge: harmless on any buffer, and where the kernel offers
// transparent huge pages on request, a fresh reserved buffer is really backed by them.
#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "metricmap/detail/huge_pages.h"

namespace metricmap {
namespace {

std::string readFile(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

/// AnonHugePages of this process, in KiB (smaps_rollup).
long anonHugeKiB() {
  std::istringstream in(readFile("/proc/self/smaps_rollup"));
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("AnonHugePages:", 0) == 0) return std::stol(line.substr(14));
  }
  return -1;
}

TEST(HugePages, AdviceIsHarmlessOnAnyBuffer) {
  adviseHugePages(nullptr, 0);
  adviseHugePages(nullptr, std::size_t{1} << 30);
  std::vector<char> small(100, 'x');
  adviseHugePages(small.data() + 1, small.size() - 1);
  EXPECT_EQ(small[50], 'x');
  std::vector<std::uint64_t> v{1, 2, 3};
  reserveHuge(v, 1 << 20);
  EXPECT_GE(v.capacity(), std::size_t{1} << 20);
  ASSERT_EQ(v.size(), 3u);  // contents kept
  EXPECT_EQ(v[2], 3u);
  reserveHuge(v, 10);  // never shrinks
  EXPECT_GE(v.capacity(), std::size_t{1} << 20);
}

TEST(HugePages, AFreshReservedBufferIsBackedByHugePagesWhenTheKernelOffersThem) {
  const std::string mode = readFile("/sys/kernel/mm/transparent_hugepage/enabled");
  const bool offered =
      mode.find("[madvise]") != std::string::npos || mode.find("[always]") != std::string::npos;
  const long before = anonHugeKiB();
  if (!offered || before < 0) {
    GTEST_SKIP() << "transparent huge pages are not offered on request here (mode: " << mode
                 << "); nothing to measure";
  }
  std::vector<std::uint64_t> v;
  reserveHuge(v, std::size_t{32} << 20 >> 3);  // 32 MiB, untouched
  v.resize(v.capacity(), 7);                   // first touch
  const long after = anonHugeKiB();
  EXPECT_GE(after - before, 8 * 1024) << "THP mode: " << mode;
  EXPECT_EQ(v.back(), 7u);
}

}  // namespace
}  // namespace metricmap
