#include "object_lock.h"

#include <functional>
#include <stdexcept>

namespace metricmap::python {

ObjectGuard::ObjectGuard(ObjectMutex& m, const char* what) : m_(m) {
  if (m.owner_.load() == std::this_thread::get_id())
    throw std::runtime_error(std::string(what) +
                             " is busy in this thread (called from its own progress callback?)");
  if (!m.mutex_.try_lock()) {
    py::gil_scoped_release release;  // the holder may need the GIL to finish
    m.mutex_.lock();
  }
  m.owner_.store(std::this_thread::get_id());
}

ObjectGuard::~ObjectGuard() {
  m_.owner_.store(std::thread::id());
  m_.mutex_.unlock();
}

PairGuard::PairGuard(ObjectMutex& a, ObjectMutex& b, const char* what) {
  ObjectMutex* lo = std::less<ObjectMutex*>()(&a, &b) ? &a : &b;
  ObjectMutex* hi = lo == &a ? &b : &a;
  first_.emplace(*lo, what);
  if (hi != lo) second_.emplace(*hi, what);
}

}  // namespace metricmap::python
