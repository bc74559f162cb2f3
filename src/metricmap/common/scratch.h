#pragma once
/// \file scratch.h
/// \brief Scratch memory a builder keeps between calls, behind a pointer so that public
/// headers need not see its type.

#include <memory>

namespace metricmap {

/// \brief Owns a `W`, made on first use where `W` is complete; a copy starts with none (the
/// scratch of one object is never shared with another). release() gives the memory back.
template <typename W>
class Scratch {
 public:
  Scratch() = default;
  Scratch(const Scratch&) {}
  Scratch& operator=(const Scratch&) { return *this; }
  Scratch(Scratch&&) noexcept = default;
  Scratch& operator=(Scratch&&) noexcept = default;
  ~Scratch() = default;

  /// \brief The scratch, made on first use (needs `W` complete at the call).
  W& get() {
    if (!w_) w_ = Owned(new W(), [](W* w) { delete w; });
    return *w_;
  }
  /// \brief Free the scratch; the next build allocates afresh.
  void release() { w_.reset(); }

 private:
  using Owned = std::unique_ptr<W, void (*)(W*)>;
  Owned w_{nullptr, nullptr};
};

}  // namespace metricmap
