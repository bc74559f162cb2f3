#include "metricmap/common/memory_budget.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "metricmap/common/parse_number.h"
#include "metricmap/exceptions.h"

namespace metricmap {
namespace {

std::uint64_t physicalMemory() {
  const long pages = ::sysconf(_SC_PHYS_PAGES);
  const long page = ::sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page <= 0) return std::uint64_t{4} << 30;
  return static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(page);
}

std::atomic<std::uint64_t>& budget() {
  static std::atomic<std::uint64_t> b{std::max<std::uint64_t>(physicalMemory() / 2, 256u << 20)};
  return b;
}

std::string mib(std::uint64_t bytes) {
  return std::to_string((bytes + (1u << 20) - 1) >> 20) + " MiB";
}

}  // namespace

std::uint64_t memoryBudget() { return budget().load(); }

void setMemoryBudget(std::uint64_t bytes) {
  if (bytes == 0) throw std::invalid_argument("memory budget must be positive");
  budget().store(bytes);
}

std::uint64_t parseByteSize(const std::string& text, const std::string& what) {
  std::string number = text;
  double unit = 1.0;
  if (!number.empty()) {
    switch (number.back()) {
      case 'K':
      case 'k':
        unit = 1024.0;
        break;
      case 'M':
      case 'm':
        unit = 1024.0 * 1024;
        break;
      case 'G':
      case 'g':
        unit = 1024.0 * 1024 * 1024;
        break;
      case 'T':
      case 't':
        unit = 1024.0 * 1024 * 1024 * 1024;
        break;
      default:
        break;
    }
    if (unit != 1.0) number.pop_back();
  }
  const double value = parseFiniteDouble(number, what) * unit;
  if (!(value >= 1.0) || value > 9.0e18)
    throw std::invalid_argument(what + ": '" + quoteForMessage(text) +
                                "' is not a size between 1 byte and 8 EiB");
  return static_cast<std::uint64_t>(value);
}

void checkMemory(std::uint64_t count, std::uint64_t item_bytes, const std::string& what) {
  const std::uint64_t limit = memoryBudget();
  if (item_bytes != 0 && count > limit / item_bytes) {
    const long double need = static_cast<long double>(count) * item_bytes;
    const std::uint64_t shown =
        need >= static_cast<long double>(std::numeric_limits<std::uint64_t>::max())
            ? std::numeric_limits<std::uint64_t>::max()
            : static_cast<std::uint64_t>(need);
    throw CapacityError(what + " needs " + mib(shown) + ", more than the memory budget of " +
                        mib(limit) + " (--max-memory)");
  }
}

}  // namespace metricmap
