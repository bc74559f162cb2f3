#pragma once
/// \file chunk_buffer.h
/// \brief Internal to the bag readers: a byte vector whose resize does not zero the bytes, so
/// that a chunk declaring more uncompressed bytes than its data gives (within the memory
/// budget) costs address space, not resident memory, until decompression fails on the size.

#include <cstdint>
#include <memory>
#include <new>
#include <vector>

namespace metricmap::detail {

template <class T>
struct DefaultInitAllocator : std::allocator<T> {
  template <class U>
  struct rebind {
    using other = DefaultInitAllocator<U>;
  };
  DefaultInitAllocator() = default;
  template <class U>
  DefaultInitAllocator(const DefaultInitAllocator<U>&) noexcept {}
  template <class U>
  void construct(U* p) noexcept {
    ::new (static_cast<void*>(p)) U;  // default-initialised: no zeroing
  }
  template <class U, class... A>
  void construct(U* p, A&&... a) {
    ::new (static_cast<void*>(p)) U(std::forward<A>(a)...);
  }
};

using ChunkBuffer = std::vector<std::uint8_t, DefaultInitAllocator<std::uint8_t>>;

}  // namespace metricmap::detail
