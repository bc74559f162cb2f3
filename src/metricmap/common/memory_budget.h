#pragma once
/// \file memory_budget.h
/// \brief One process-wide memory budget, checked before large allocations driven by input.

#include <cstdint>
#include <string>

namespace metricmap {

/// \brief The budget in bytes: by default half of the physical memory (at least 256 MiB).
std::uint64_t memoryBudget();

/// \brief Replace the budget (the CLI's --max-memory). \throws std::invalid_argument if 0
void setMemoryBudget(std::uint64_t bytes);

/// \brief Parse "512M", "2G", "1.5G", "100000" (bytes; suffixes K, M, G, T are powers of 1024).
/// \throws std::invalid_argument naming `what` and the text
std::uint64_t parseByteSize(const std::string& text, const std::string& what);

/// \brief Throw CapacityError unless `count` items of `item_bytes` each fit in the budget.
/// \param what names the input or option that asked for the memory ("t.png: 30000 x 30000 pixels")
void checkMemory(std::uint64_t count, std::uint64_t item_bytes, const std::string& what);

/// \brief checkMemory for an allocation made while `held` bytes are in use by the same work
/// (the other maps of a pipeline): the sum must fit in the budget.
void checkMemoryBeside(std::uint64_t count, std::uint64_t item_bytes, std::uint64_t held,
                       const std::string& what);

}  // namespace metricmap
