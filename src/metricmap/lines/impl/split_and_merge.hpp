#pragma once

#include <cmath>
#include <stdexcept>

#include "metricmap/lines/split_and_merge.h"

namespace metricmap {

template <typename PointT>
void SplitAndMerge<PointT>::segment(std::vector<LineSegment>& segments,
                                    std::vector<pcl::PointIndices>& members) {
  segments.clear();
  members.clear();
  if (!input_) throw std::invalid_argument("SplitAndMerge: no input cloud set");
  if (!initCompute()) throw std::invalid_argument("SplitAndMerge: invalid input or indices");
  std::vector<Eigen::Vector2d> xy;
  std::vector<int> beams;
  xy.reserve(indices_->size());
  beams.reserve(indices_->size());
  for (const int i : *indices_) {
    const PointT& p = (*input_)[static_cast<std::size_t>(i)];
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) continue;
    xy.emplace_back(p.x, p.y);
    beams.push_back(i);
  }
  std::vector<std::vector<int>> beam_members;
  segments = splitAndMerge(xy, beams, params_, step_ ? &step_ : nullptr, &beam_members);
  members.resize(beam_members.size());
  for (std::size_t k = 0; k < beam_members.size(); ++k) {
    members[k].header = input_->header;
    members[k].indices.assign(beam_members[k].begin(), beam_members[k].end());
  }
  deinitCompute();
}

}  // namespace metricmap
