#pragma once
/// \file parallel.h
/// \brief Fork-join over a few threads (std::thread), for the builders' passes.

#include <algorithm>
#include <cstddef>
#include <exception>
#include <thread>
#include <utility>
#include <vector>

namespace metricmap {

/// \brief Threads to use for `requested` (0: all hardware threads), at most one per `grain`
/// items of work and at least one.
inline unsigned resolveThreads(unsigned requested, std::size_t items, std::size_t grain) {
  unsigned t = requested == 0 ? std::max(1u, std::thread::hardware_concurrency()) : requested;
  const std::size_t by_work = std::max<std::size_t>(1, items / std::max<std::size_t>(1, grain));
  return static_cast<unsigned>(std::min<std::size_t>(t, by_work));
}

/// \brief [begin, end) of chunk t of `n` items split into `threads` near-equal chunks.
inline std::pair<std::size_t, std::size_t> chunkOf(std::size_t n, unsigned threads, unsigned t) {
  const std::size_t base = n / threads, extra = n % threads;
  const std::size_t begin = t * base + std::min<std::size_t>(t, extra);
  return {begin, begin + base + (t < extra ? 1 : 0)};
}

/// \brief Run fn(t) for t in [0, threads), t = 0 on the calling thread; rethrows the first
/// exception (by thread number) after every thread has finished.
template <typename Fn>
void parallelRun(unsigned threads, Fn&& fn) {
  if (threads <= 1) {
    fn(0u);
    return;
  }
  std::vector<std::exception_ptr> errors(threads);
  std::vector<std::thread> pool;
  pool.reserve(threads - 1);
  for (unsigned t = 1; t < threads; ++t) {
    pool.emplace_back([&, t] {
      try {
        fn(t);
      } catch (...) {
        errors[t] = std::current_exception();
      }
    });
  }
  try {
    fn(0u);
  } catch (...) {
    errors[0] = std::current_exception();
  }
  for (std::thread& th : pool) th.join();
  for (const std::exception_ptr& e : errors) {
    if (e) std::rethrow_exception(e);
  }
}

/// \brief An allocator that leaves new elements of trivial types uninitialised, so that
/// resize() does not touch fresh pages (the threads that fill them do).
template <typename T>
struct UninitAllocator : std::allocator<T> {
  template <typename U>
  struct rebind {
    using other = UninitAllocator<U>;
  };
  UninitAllocator() = default;
  template <typename U>
  UninitAllocator(const UninitAllocator<U>&) noexcept {}
  template <typename U>
  void construct(U* p) noexcept {
    ::new (static_cast<void*>(p)) U;
  }
  template <typename U, typename... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

}  // namespace metricmap
