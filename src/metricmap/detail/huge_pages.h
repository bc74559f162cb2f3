#pragma once
/// \file huge_pages.h
/// \brief Ask the kernel for transparent huge pages under a large, not yet touched buffer.
///
/// Fresh memory is costly where every 4 KiB page faults separately (about 0.5 ms per MiB in
/// the project's VM, docs/BENCHMARKS.md); with 2 MiB pages a fresh grid build over 3.7 M
/// points runs about a third faster. Call it after reserve() and before the first write.

#include <cstddef>
#include <vector>

namespace metricmap {

/// \brief madvise(MADV_HUGEPAGE) on the 2 MiB-aligned part of [p, p + bytes); a no-op for
/// small buffers and where the call does not exist. Never fails: it is only advice.
void adviseHugePages(const void* p, std::size_t bytes);

/// \brief Write one byte of every 4 KiB page of [p, p + bytes) (allocated, not yet holding
/// objects), so that the calling thread takes the page faults.
void touchPages(void* p, std::size_t bytes);

/// \brief reserve(n), then the advice on the whole capacity.
template <typename T, typename A>
void reserveHuge(std::vector<T, A>& v, std::size_t n) {
  if (v.capacity() >= n) return;  // already backed (and advised when it was reserved)
  v.reserve(n);
  adviseHugePages(v.data(), v.capacity() * sizeof(T));
}

}  // namespace metricmap
