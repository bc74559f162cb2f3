#include "metricmap/distance/distance_field.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "metricmap/common/memory_budget.h"
#include "metricmap/detail/parallel.h"
#include "metricmap/distance/distance_work.h"
#include "metricmap/exceptions.h"

namespace metricmap {

namespace {

/// Writes one transform's last pass into the field: every voxel, or only those of one side.
class FieldSink : public detail::EdtSink {
 public:
  FieldSink(std::vector<float>& field, const std::vector<std::uint8_t>& obstacle,
            const std::array<std::size_t, 3>& shape, std::uint32_t cap, double max_distance,
            double resolution, int side)
      : field_(field),
        obstacle_(obstacle),
        shape_(shape),
        cap_(cap),
        max_(max_distance),
        res_(resolution),
        side_(side) {
    // the values of the squared distances below the cap, computed once (the same formula)
    if (cap <= kTableLimit) {
      table_.resize(std::size_t{cap} + 1);
      for (std::uint32_t d2 = 0; d2 <= cap; ++d2) table_[d2] = distanceValue(d2, cap, max_, res_);
    }
  }
  void line(std::size_t j, std::size_t k, std::size_t i0, std::size_t i1,
            const std::uint32_t* d2) override {
    const std::size_t stride = shape_[1] * shape_[2], base = j * shape_[2] + k;
    for (std::size_t i = i0; i < i1; ++i) {
      const std::size_t at = base + i * stride;
      // side 0: every voxel; 1: non-obstacles (positive); -1: obstacles (negative)
      if (side_ == 1 && obstacle_[at]) continue;
      if (side_ == -1 && !obstacle_[at]) continue;
      const std::uint32_t q = d2[i - i0];
      const float v = table_.empty() ? distanceValue(q, cap_, max_, res_) : table_[q];
      field_[at] = side_ == -1 ? -v : v;
    }
  }
  static constexpr std::uint32_t kTableLimit = 1u << 16;
  static float distanceValue(std::uint32_t d2, std::uint32_t cap, double max_d, double res) {
    if (d2 >= cap) return static_cast<float>(max_d);
    return static_cast<float>(std::min(max_d, std::sqrt(static_cast<double>(d2)) * res));
  }

 private:
  std::vector<float>& field_;
  const std::vector<std::uint8_t>& obstacle_;
  std::array<std::size_t, 3> shape_;
  std::uint32_t cap_;
  double max_, res_;
  int side_;
  std::vector<float> table_;  // value of d2 for d2 <= cap_ (when cap_ <= kTableLimit)
};

std::string boxText(const OccupancyBox& box) {
  std::ostringstream s;
  s << box.shape[0] << " x " << box.shape[1];
  if (box.dimensions == 3) s << " x " << box.shape[2];
  s << " voxels at " << box.resolution << " m";
  return s.str();
}

}  // namespace

DistanceField::DistanceField(OccupancyBox box, const DistanceFieldParams& params)
    : box_(std::move(box)), params_(params), work_(std::make_unique<Work>()) {
  validateDistanceFieldParams(params_);
  if (box_.voxels() == 0 || box_.state.size() != box_.voxels())
    throw std::invalid_argument("distance field: empty box or states not matching its shape");
  if (!(box_.resolution > 0.0) || !std::isfinite(box_.resolution))
    throw std::invalid_argument("distance field: resolution must be finite and > 0");
  const double r = params_.max_distance / box_.resolution;
  if (r > 65535.0) {
    std::ostringstream msg;
    msg << "distance field: max distance " << params_.max_distance << " m is " << r << " voxels at "
        << box_.resolution << " m (at most 65535)";
    throw CapacityError(msg.str());
  }
  cap_ = static_cast<std::uint32_t>(std::floor(r * r)) + 1;
  checkMemory(box_.voxels(), distanceFieldBytesPerVoxel(params_) - 1,
              "distance field of " + boxText(box_));
  const std::size_t n = box_.voxels();
  for (int a = 0; a < 3; ++a) work_->shape.n[a] = box_.shape[a];
  const int transforms = params_.signed_distance ? 2 : 1;
  for (int t = 0; t < transforms; ++t) {
    work_->site[t].resize(n);
    if (params_.incremental) {
      work_->pass1[t].resize(n);
      work_->pass2[t].resize(n);
    }
  }
  if (!params_.incremental) work_->shared.resize(n);
  field_.resize(n);
  for (std::size_t v = 0; v < n; ++v) {
    const bool o = obstacleState(box_.state[v]);
    work_->site[0][v] = o;
    if (transforms == 2) work_->site[1][v] = !o;
  }
  std::size_t lines = 0;
  compute(nullptr, lines);
}

DistanceField::~DistanceField() = default;
DistanceField::DistanceField(DistanceField&&) noexcept = default;
DistanceField& DistanceField::operator=(DistanceField&&) noexcept = default;

float DistanceField::value(std::uint32_t d2) const {
  return FieldSink::distanceValue(d2, cap_, params_.max_distance, box_.resolution);
}

void DistanceField::compute(const std::vector<std::size_t>* pass1_lines, std::size_t& lines) {
  const auto start = std::chrono::steady_clock::now();
  const int transforms = params_.signed_distance ? 2 : 1;
  // Beyond the box: obstacles when unknown space is (the obstacle transform), non-obstacles
  // otherwise (the complement's). A 2D box has nothing beyond it along z.
  const bool outside_obstacle = params_.unknown == UnknownAs::Occupied;
  for (int t = 0; t < transforms; ++t) {
    detail::EdtTransform tr;
    tr.site = work_->site[t].data();
    const bool border = t == 0 ? outside_obstacle : !outside_obstacle;
    tr.border = {border, border, border && box_.dimensions == 3};
    tr.cap = cap_;
    if (params_.incremental) {
      tr.pass1 = work_->pass1[t].data();
      tr.pass2 = work_->pass2[t].data();
    } else {
      tr.pass1 = tr.pass2 = work_->shared.data();
    }
    const int side = transforms == 1 ? 0 : (t == 0 ? 1 : -1);
    FieldSink sink(field_, work_->site[0], box_.shape, cap_, params_.max_distance, box_.resolution,
                   side);
    std::unique_ptr<detail::EdtDirtyLines> dirty;
    if (pass1_lines != nullptr) {
      dirty = std::make_unique<detail::EdtDirtyLines>(work_->shape);
      for (std::size_t l : *pass1_lines) dirty->markPass1(l / box_.shape[1], l % box_.shape[1]);
    }
    lines += detail::runEdt(work_->shape, tr, sink, params_.threads, dirty.get());
  }
  seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

bool DistanceField::isObstacle(std::size_t i, std::size_t j, std::size_t k) const {
  return work_->site[0][index(i, j, k)] != 0;
}

std::size_t DistanceField::occupiedVoxels() const {
  return static_cast<std::size_t>(
      std::count(box_.state.begin(), box_.state.end(), std::uint8_t{kVoxelOccupied}));
}
std::size_t DistanceField::unknownVoxels() const {
  return static_cast<std::size_t>(
      std::count(box_.state.begin(), box_.state.end(), std::uint8_t{kVoxelUnknown}));
}
std::size_t DistanceField::obstacleVoxels() const {
  return static_cast<std::size_t>(
      std::count(work_->site[0].begin(), work_->site[0].end(), std::uint8_t{1}));
}
std::size_t DistanceField::clampedVoxels() const {
  const auto m = static_cast<float>(params_.max_distance);
  return static_cast<std::size_t>(
      std::count_if(field_.begin(), field_.end(), [m](float v) { return v >= m; }));
}
std::size_t DistanceField::bytes() const {
  std::size_t b = field_.capacity() * 4 + box_.state.capacity() + work_->shared.capacity() * 4;
  for (int t = 0; t < 2; ++t) {
    b += work_->site[t].capacity() + 4 * (work_->pass1[t].capacity() + work_->pass2[t].capacity());
  }
  return b;
}

}  // namespace metricmap
