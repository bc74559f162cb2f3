#include "metricmap/detail/thread_team.h"

#include <chrono>

namespace metricmap {
namespace {

// Spin (yielding) while `busy()` holds, for at most 200 microseconds; the callers then sleep.
template <class Busy>
void spinWhile(Busy busy) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::microseconds(200);
  while (busy() && std::chrono::steady_clock::now() < until) std::this_thread::yield();
}

}  // namespace

ThreadTeam::ThreadTeam(unsigned threads) : errors_(threads < 1 ? 1 : threads) {
  try {
    workers_.reserve(threads);
    for (unsigned t = 1; t < threads; ++t) workers_.emplace_back([this, t] { work(t); });
  } catch (...) {
    stopWorkers();  // a thread that cannot be started: stop those that were
    throw;
  }
}

ThreadTeam::~ThreadTeam() { stopWorkers(); }

void ThreadTeam::stopWorkers() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
    published_.store(~std::uint64_t{0}, std::memory_order_release);
  }
  wake_.notify_all();
  for (std::thread& w : workers_) w.join();
}

void ThreadTeam::run(const std::function<void(unsigned)>& fn) {
  if (workers_.empty()) {
    fn(0u);
    return;
  }
  {
    std::lock_guard<std::mutex> lock(mutex_);
    job_ = &fn;
    pending_.store(static_cast<unsigned>(workers_.size()), std::memory_order_relaxed);
    ++generation_;
    published_.store(generation_, std::memory_order_release);
    for (std::exception_ptr& e : errors_) e = nullptr;
  }
  wake_.notify_all();
  try {
    fn(0u);
  } catch (...) {
    errors_[0] = std::current_exception();
  }
  spinWhile([this] { return pending_.load(std::memory_order_acquire) != 0; });
  {
    std::unique_lock<std::mutex> lock(mutex_);
    done_.wait(lock, [this] { return pending_.load(std::memory_order_acquire) == 0; });
    job_ = nullptr;
  }
  for (const std::exception_ptr& e : errors_) {
    if (e) std::rethrow_exception(e);
  }
}

void ThreadTeam::work(unsigned t) {
  std::uint64_t seen = 0;
  for (;;) {
    // A run usually follows the last one within microseconds (the next Gauss-Newton step).
    spinWhile([&] { return published_.load(std::memory_order_acquire) == seen; });
    const std::function<void(unsigned)>* job = nullptr;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [&] { return stop_ || generation_ != seen; });
      if (stop_) return;
      seen = generation_;
      job = job_;
    }
    try {
      (*job)(t);
    } catch (...) {
      errors_[t] = std::current_exception();
    }
    if (pending_.fetch_sub(1, std::memory_order_acq_rel) == 1) {
      // Taking the lock orders this notification after the caller's check under it.
      std::lock_guard<std::mutex> lock(mutex_);
      done_.notify_one();
    }
  }
}

}  // namespace metricmap
