// The memory budget: sizes parsed exactly, requests above the budget refused with a message
// naming the request.
#include <unistd.h>

#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "metricmap/common/memory_budget.h"
#include "metricmap/exceptions.h"

namespace metricmap {

TEST(MemoryBudget, ParsesSizes) {
  EXPECT_EQ(parseByteSize("100000", "m"), 100000u);
  EXPECT_EQ(parseByteSize("2K", "m"), 2048u);
  EXPECT_EQ(parseByteSize("512M", "m"), 512ull << 20);
  EXPECT_EQ(parseByteSize("1.5G", "m"), 3ull << 29);
  EXPECT_EQ(parseByteSize("1T", "m"), 1ull << 40);
  for (const char* t : {"", "G", "-1G", "0", "nan", "1e30", "lots", "0x10", "1GB"})
    EXPECT_THROW(parseByteSize(t, "--max-memory"), std::invalid_argument) << t;
}

TEST(MemoryBudget, DefaultIsAFractionOfPhysicalMemory) {
  const std::uint64_t b = memoryBudget();
  EXPECT_GE(b, 256ull << 20);
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGE_SIZE);
  EXPECT_LE(b, static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(page));
}

TEST(MemoryBudget, RefusesLargeRequestsNamingThem) {
  const std::uint64_t saved = memoryBudget();
  setMemoryBudget(1 << 20);
  EXPECT_NO_THROW(checkMemory(1 << 18, 4, "small"));
  try {
    checkMemory((1 << 18) + 1, 4, "--map-size 512");
    FAIL();
  } catch (const CapacityError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("--map-size 512"), std::string::npos) << m;
    EXPECT_NE(m.find("budget of 1 MiB"), std::string::npos) << m;
  }
  EXPECT_THROW(checkMemory(~0ull, ~0ull, "overflow"), CapacityError);  // no wrap-around
  EXPECT_THROW(setMemoryBudget(0), std::invalid_argument);
  setMemoryBudget(saved);
}

}  // namespace metricmap
