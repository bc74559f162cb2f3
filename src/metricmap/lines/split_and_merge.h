#pragma once
/// \file split_and_merge.h
/// \brief metricmap::SplitAndMerge — straight segments from an ordered 2D scan, PCL style.

#include <memory>
#include <vector>

#include <pcl/PointIndices.h>
#include <pcl/pcl_base.h>

#include "metricmap/lines/line_segment.h"
#include "metricmap/lines/split_and_merge_kernel.h"
#include "metricmap/lines/split_and_merge_types.h"

namespace metricmap {

/// \brief Split & Merge line extraction on x and y of an ordered cloud (cloud order = beam
/// order; a beam's index is its position in the cloud; NaN points are invalid beams).
///
/// Split: from (first, last), the point farthest from the chord splits it when its distance
/// exceeds d_th (or its chi-square score exceeds the threshold); iterative, no point dropped;
/// the farthest point closes the first half. A chord shorter than d_th (a closed 360-degree scan)
/// has no direction, so distances are then measured from its start point.
/// Merge: neighbours whose directions differ by less than a_th (difference wrapped to
/// (-pi, pi]) become one, and the result is compared with the next. Purge: segments with fewer
/// points or shorter than the limits go, before merge by default (see PurgeOrder).
/// \note Thread safety: one instance per thread.
template <typename PointT>
class SplitAndMerge : public pcl::PCLBase<PointT> {
 protected:
  using pcl::PCLBase<PointT>::input_;
  using pcl::PCLBase<PointT>::indices_;
  using pcl::PCLBase<PointT>::initCompute;
  using pcl::PCLBase<PointT>::deinitCompute;

 public:
  using Ptr = std::shared_ptr<SplitAndMerge<PointT>>;
  using ConstPtr = std::shared_ptr<const SplitAndMerge<PointT>>;

  /// \throws std::invalid_argument naming the bad value
  void setParams(const SplitAndMergeParams& params) {
    validateSplitAndMergeParams(params);
    params_ = params;
  }
  const SplitAndMergeParams& getParams() const { return params_; }
  void setDistanceThreshold(double d) { setField(&SplitAndMergeParams::distance_threshold, d); }
  void setAngleThreshold(double radians) {
    setField(&SplitAndMergeParams::angle_threshold, radians);
  }
  void setMinPoints(std::size_t n) { params_.min_points = n; }
  void setMinLength(double l) { setField(&SplitAndMergeParams::min_length, l); }
  void setMaxGap(double g) { setField(&SplitAndMergeParams::max_gap, g); }
  void setPurgeOrder(PurgeOrder order) { params_.purge_order = order; }

  /// \brief Called after every split, merge and purge step (for drawings); empty to stop.
  void setStepCallback(SplitAndMergeStep step) { step_ = std::move(step); }

  /// \brief Segment the input (through the indices, if set, in their order).
  /// \param[out] segments in scan order, with fits
  /// \param[out] members beam indices of each segment's points
  void segment(std::vector<LineSegment>& segments, std::vector<pcl::PointIndices>& members);

 private:
  void setField(double SplitAndMergeParams::*field, double value) {
    SplitAndMergeParams p = params_;
    p.*field = value;
    setParams(p);
  }

  SplitAndMergeParams params_;
  SplitAndMergeStep step_;
};

}  // namespace metricmap

#ifdef METRICMAP_NO_PRECOMPILE
#include "metricmap/lines/impl/split_and_merge.hpp"
#else
#include <pcl/point_types.h>
extern template class metricmap::SplitAndMerge<pcl::PointXYZ>;
extern template class metricmap::SplitAndMerge<pcl::PointXYZI>;
extern template class metricmap::SplitAndMerge<pcl::PointXYZRGB>;
#endif
