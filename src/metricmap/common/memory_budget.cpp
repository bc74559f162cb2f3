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

/// Rounded up, without overflow near 2^64 (bytes + 2^20 - 1 would wrap to "0 MiB").
std::string mib(std::uint64_t bytes) {
  return std::to_string((bytes >> 20) + ((bytes & ((1u << 20) - 1)) != 0 ? 1 : 0)) + " MiB";
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
    // exact in 128 bits: count x item_bytes may exceed 64 bits, and the size shown must be the
    // real one, not a saturated or wrapped value
    __extension__ typedef unsigned __int128 U128;  // GCC/Clang; __extension__: no -Wpedantic
    U128 need_mib = (static_cast<U128>(count) * item_bytes + ((1u << 20) - 1)) >> 20;
    std::string shown;
    do {
      shown.insert(shown.begin(), static_cast<char>('0' + static_cast<int>(need_mib % 10)));
      need_mib /= 10;
    } while (need_mib != 0);
    shown += " MiB";
    throw CapacityError(what + " needs " + shown + ", more than the memory budget of " +
                        mib(limit) + " (--max-memory)");
  }
}

void checkMemoryBeside(std::uint64_t count, std::uint64_t item_bytes, std::uint64_t held,
                       const std::string& what) {
  const std::uint64_t limit = memoryBudget();
  if (held == 0) return checkMemory(count, item_bytes, what);
  __extension__ typedef unsigned __int128 U128;  // GCC/Clang; __extension__: no -Wpedantic
  const U128 need = static_cast<U128>(count) * item_bytes;
  if (need + held > limit) {
    const U128 need_mib = (need + ((1u << 20) - 1)) >> 20;
    const std::string shown = need_mib > 0xFFFFFFFFFFFFull
                                  ? "more than 2^48 MiB"
                                  : std::to_string(static_cast<std::uint64_t>(need_mib)) + " MiB";
    throw CapacityError(what + " needs " + shown + " beside the " + mib(held) +
                        " already held, more than the memory budget of " + mib(limit) +
                        " (--max-memory)");
  }
}

}  // namespace metricmap
