#pragma once
/// \file adaptive_threshold.h
/// \brief Correspondence threshold from the recent errors of the motion prediction.

#include <cstddef>

#include <Eigen/Geometry>

namespace metricmap {

/// \brief Tracks how far the registered pose lands from the predicted one, in metres (the
/// translation plus the chord a rotation error sweeps at `lever` metres), and turns the root
/// mean square of these deviations into a threshold of three standard deviations. Every frame
/// counts, a standing one too, but no deviation counts as less than `min_deviation`: a stop
/// then keeps the threshold at 3 min_deviation instead of leaving it at its initial width.
class AdaptiveThreshold {
 public:
  /// \param initial_sigma deviation assumed until the first frame is recorded
  /// \param min_threshold floor of threshold()
  AdaptiveThreshold(double initial_sigma, double min_threshold, double min_deviation, double lever)
      : initial_sigma_(initial_sigma),
        min_threshold_(min_threshold),
        min_deviation_(min_deviation),
        lever_(lever) {}

  /// \brief Record one frame: `deviation` = predicted^-1 * registered pose.
  void update(const Eigen::Isometry3d& deviation);
  /// \brief Three standard deviations, at least min_threshold.
  double threshold() const;
  /// \brief Frames recorded so far.
  std::size_t samples() const { return samples_; }

  /// \brief The deviation of `d` in metres: |t| + 2 lever sin(angle / 2).
  static double deviationMetres(const Eigen::Isometry3d& d, double lever);

 private:
  double initial_sigma_, min_threshold_, min_deviation_, lever_;
  double sum_sq_ = 0.0;
  std::size_t samples_ = 0;
};

}  // namespace metricmap
