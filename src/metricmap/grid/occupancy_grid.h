#pragma once
/// \file occupancy_grid.h
/// \brief metricmap::OccupancyGrid — a fixed-resolution voxel grid (count + mean) as a PCL filter.

#include <array>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <vector>

#include <pcl/filters/filter.h>

#include "metricmap/common/scratch.h"
#include "metricmap/grid/grid_types.h"

namespace metricmap {

/// \brief Bins a cloud into cubic cells; `filter()` gives one point per occupied cell, at the
/// mean of its points. Non-coordinate fields (intensity, colour) are those of the cell's
/// first input point.
///
/// With GridOrigin::CloudMinimum (default, the study's partition) the index is
/// floor((p - min) / cell) computed in double; a coordinate within float32 rounding of a cell
/// boundary counts as lying on it (so decimal data such as "1.500" lands where its decimal
/// value does). With GridOrigin::WorldAligned the index is floor(p * (1/cell)) in float,
/// bit for bit the partition of pcl::VoxelGrid, without its 32-bit index limit.
/// Cell keys are 64-bit: any grid whose total cell count fits in 64 bits works.
///
/// The build keys every point by its linear cell index (x fastest) and radix-sorts the keys, so
/// cells come out in that order (pcl::VoxelGrid's order too). Scratch buffers are kept between
/// calls: reuse one instance for a stream of clouds.
/// \note Thread safety: one instance per thread; different instances share nothing.
template <typename PointT>
class OccupancyGrid : public pcl::Filter<PointT> {
 protected:
  using pcl::Filter<PointT>::filter_name_;
  using pcl::Filter<PointT>::input_;
  using pcl::Filter<PointT>::indices_;
  using pcl::Filter<PointT>::fake_indices_;

 public:
  using PointCloud = typename pcl::Filter<PointT>::PointCloud;
  using Ptr = std::shared_ptr<OccupancyGrid<PointT>>;
  using ConstPtr = std::shared_ptr<const OccupancyGrid<PointT>>;

  OccupancyGrid() { filter_name_ = "OccupancyGrid"; }

  /// \brief Edge of the cubic cells, metres.
  /// \throws std::invalid_argument unless finite and > 0
  void setCellSize(float cell_size) {
    validateCellSize(cell_size);
    params_.cell_size = cell_size;
  }
  float getCellSize() const { return params_.cell_size; }

  /// \brief Where cell (0, 0, 0) starts; see GridOrigin.
  void setOrigin(GridOrigin origin) { params_.origin = origin; }
  GridOrigin getOrigin() const { return params_.origin; }

  /// \brief Bin the input without producing a cloud (filter() does this too).
  /// \throws std::invalid_argument without an input cloud; CapacityError when too large
  /// \brief Threads for a build, in PCL's manner: 0 = all hardware threads (default), 1 = one.
  /// The result does not depend on it, bit for bit. Clouds under ~130 k points per thread use
  /// fewer threads.
  void setNumberOfThreads(unsigned threads) { params_.threads = threads; }
  unsigned getNumberOfThreads() const { return params_.threads; }

  void compute();

  /// \brief pcl::Filter::filter, except that without an input cloud it throws, as compute()
  /// does, instead of returning quietly with the output untouched.
  /// \throws std::invalid_argument without an input cloud; CapacityError when too large
  void filter(PointCloud& output) {
    if (!input_) throw std::invalid_argument(filter_name_ + ": no input cloud set");
    pcl::Filter<PointT>::filter(output);
  }

  /// \brief Figures of the last build.
  const GridStatistics& getStatistics() const { return result_.stats; }
  /// \brief Occupied cells of the last build, in linear-index order.
  const std::vector<GridCell>& getCells() const { return result_.cells; }
  /// \brief Bounding volume of the last build.
  const GridLayout& getLayout() const { return result_.layout; }
  /// \brief The occupied cell with this index, or nullptr.
  const GridCell* findCell(const std::array<std::int64_t, 3>& index) const;
  /// \brief World-space lower corner of a cell of the last build.
  Eigen::Vector3d getCellMin(const std::array<std::int64_t, 3>& index) const;

 protected:
  void applyFilter(PointCloud& output) override;

 private:
  GridParams params_;
  Scratch<GridWorkspace> workspace_;  // kept between builds
  GridResult result_;
};

}  // namespace metricmap

#ifdef METRICMAP_NO_PRECOMPILE
#include "metricmap/grid/impl/occupancy_grid.hpp"
#else
// The library instantiates every type of PCL_XYZ_POINT_TYPES; these three are the common ones.
#include <pcl/point_types.h>
extern template class metricmap::OccupancyGrid<pcl::PointXYZ>;
extern template class metricmap::OccupancyGrid<pcl::PointXYZI>;
extern template class metricmap::OccupancyGrid<pcl::PointXYZRGB>;
#endif
