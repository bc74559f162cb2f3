#pragma once
/// \file chunk_buffer.h
/// \brief Internal to the bag readers: a byte vector whose resize does not zero the bytes, so
/// that a chunk declaring more uncompressed bytes than its data gives (within the memory
/// budget) costs address space, not resident memory, until decompression fails on the size.

#include <cstdint>
#include <vector>

#include "metricmap/detail/parallel.h"

namespace metricmap::detail {

using ChunkBuffer = std::vector<std::uint8_t, UninitAllocator<std::uint8_t>>;

}  // namespace metricmap::detail
