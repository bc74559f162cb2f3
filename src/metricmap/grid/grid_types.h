#pragma once
/// \file grid_types.h
/// \brief Parameters, cells and statistics of metricmap::OccupancyGrid (no PCL needed).

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace metricmap {

/// \brief Where cell (0, 0, 0) starts.
enum class GridOrigin {
  /// The study's partition: index = floor((p - cloud_min) / cell). Default.
  CloudMinimum,
  /// pcl::VoxelGrid's partition: index = floor(p / cell), computed in float as PCL does.
  WorldAligned,
  /// Cell (0, 0, 0) starts at GridParams::origin_point: index = floor((p - origin_point) /
  /// cell), computed in double.
  Point,
  /// Open3D's voxel_down_sample: cell (0, 0, 0) starts half a cell below the cloud's minimum,
  /// index = floor((p - (min - cell / 2)) / cell), computed in double as Open3D does.
  HalfCellBelowMinimum
};

/// \brief OccupancyGrid parameters.
struct GridParams {
  float cell_size = 1.0f;  ///< edge of a cubic cell, metres; finite and > 0
  GridOrigin origin = GridOrigin::CloudMinimum;
  /// Threads for a build: 0 = all hardware threads, 1 = single-threaded. The cells, counts
  /// and means do not depend on it (bit for bit). Small clouds use fewer threads.
  unsigned threads = 0;
  /// The cell edge in double for the Point and HalfCellBelowMinimum origins (the value the
  /// caller gave, before rounding to float); 0 = cell_size.
  double exact_cell_size = 0.0;
  /// Start of cell (0, 0, 0) for GridOrigin::Point; finite.
  Eigen::Vector3d origin_point = Eigen::Vector3d::Zero();
  /// Fill GridResult::point_cells (one int64 per point).
  bool point_cells = false;
};

/// \brief Figures of one grid, as in the study's table.
struct GridStatistics {
  std::uint64_t total_cells = 0;     ///< cells of the bounding volume: prod(floor(extent/cell)+1)
  std::uint64_t occupied_cells = 0;  ///< cells holding at least one point
  std::uint64_t empty_cells = 0;     ///< total_cells - occupied_cells
  double mean_points_per_occupied_cell = 0.0;  ///< points / occupied_cells (0 when empty)
  std::uint64_t points = 0;                    ///< finite points binned (sum of cell counts)
  std::uint64_t skipped_points = 0;            ///< NaN/Inf points ignored
};

/// \brief One occupied cell.
struct GridCell {
  std::array<std::int64_t, 3> index{};             ///< integer cell index (see GridOrigin)
  std::uint64_t count = 0;                         ///< points in the cell
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();  ///< mean of its points (double sums)
  std::size_t first_point = 0;  ///< position in the input cloud of its first point
};

/// \brief The bounding volume the cells live in.
struct GridLayout {
  std::array<std::int64_t, 3> min_index{};           ///< index of the lowest cell per axis
  std::array<std::uint64_t, 3> dims{};               ///< cells per axis
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();  ///< world position of index (0, 0, 0)
  double cell_size = 0.0;
};

/// \brief Everything a grid build produces. Cells are sorted by their linear index
/// (x fastest, then y, then z), the order pcl::VoxelGrid outputs too.
struct GridResult {
  GridLayout layout;
  std::vector<GridCell> cells;
  GridStatistics stats;
  /// When GridParams::point_cells: per point of the input view, the position in `cells` of
  /// its cell, -1 for a skipped (NaN/Inf) point. Empty otherwise.
  std::vector<std::int64_t> point_cells;
};

/// \brief Throws std::invalid_argument unless the cell size is finite and > 0.
void validateCellSize(float cell_size);

/// \brief Throws std::invalid_argument for a bad cell size (float or exact) or a non-finite
/// GridOrigin::Point start.
void validateGridParams(const GridParams& params);

/// \brief Scratch memory of a grid build (defined in grid_kernel.h).
struct GridWorkspace;

}  // namespace metricmap
