#pragma once
/// \file thread_team.h
/// \brief A fork-join team of threads kept between calls, for loops too short to start threads
/// for each time (a Gauss-Newton step of the odometry takes a fraction of a millisecond).

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace metricmap {

/// \brief `size()` threads, the calling one included: run(fn) calls fn(t) for t in [0, size())
/// with t = 0 on the caller, and returns when all are done. Workers wait for the next run()
/// spinning briefly, then asleep. Not for concurrent run() calls from several threads.
class ThreadTeam {
 public:
  /// \param threads team size, at least 1 (1: run() calls fn(0) and nothing else)
  /// \throws std::system_error when a thread cannot be started (none is left running)
  explicit ThreadTeam(unsigned threads);
  ~ThreadTeam();
  ThreadTeam(const ThreadTeam&) = delete;
  ThreadTeam& operator=(const ThreadTeam&) = delete;

  unsigned size() const { return static_cast<unsigned>(workers_.size()) + 1; }
  /// \brief Rethrows the first exception (by thread number) after every thread has finished.
  void run(const std::function<void(unsigned)>& fn);

 private:
  void work(unsigned t);
  void stopWorkers();

  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  const std::function<void(unsigned)>* job_ = nullptr;
  std::uint64_t generation_ = 0;  // guarded by mutex_; also mirrored in published_
  std::atomic<std::uint64_t> published_{0};
  std::atomic<unsigned> pending_{0};  // workers still running the current job
  bool stop_ = false;                 // guarded by mutex_
  std::vector<std::exception_ptr> errors_;
};

}  // namespace metricmap
