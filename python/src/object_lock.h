#pragma once
/// \file object_lock.h
/// \brief Python objects shared between threads: each object serialises its own calls. A call
/// holds the object's mutex from its start to its end; a second thread waits (with the GIL
/// released, since the holder may need the GIL for a progress callback); a call made from
/// within the object's own call (a progress callback calling the object) is refused.

#include <atomic>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "arrays.h"

namespace metricmap::python {

/// \brief The mutex of one Python object. A copy of the object gets a mutex of its own.
class ObjectMutex {
 public:
  ObjectMutex() = default;
  ObjectMutex(const ObjectMutex&) {}
  ObjectMutex& operator=(const ObjectMutex&) { return *this; }

 private:
  friend class ObjectGuard;
  std::mutex mutex_;
  std::atomic<std::thread::id> owner_{};
};

/// \brief Holds an object's mutex for one call. Made with the GIL held.
class ObjectGuard {
 public:
  /// \throws std::runtime_error (RuntimeError) when this thread already holds it; `what`
  /// names the object in that message
  ObjectGuard(ObjectMutex& m, const char* what);
  ~ObjectGuard();
  ObjectGuard(const ObjectGuard&) = delete;
  ObjectGuard& operator=(const ObjectGuard&) = delete;

 private:
  ObjectMutex& m_;
};

}  // namespace metricmap::python

namespace metricmap::python {

/// \brief The guards of two objects' mutexes (one when they are the same object), taken in
/// address order so that a.f(b) and b.f(a) in two threads cannot deadlock.
class PairGuard {
 public:
  PairGuard(ObjectMutex& a, ObjectMutex& b, const char* what);

 private:
  std::optional<ObjectGuard> first_, second_;
};

}  // namespace metricmap::python
