#pragma once
/// \file map_2d.h
/// \brief A loaded 2D occupancy map: cells in nav_msgs/OccupancyGrid's convention, placed in the
/// world by a resolution and the pose of the grid's lower-left corner.

#include <cmath>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "metricmap/common/pose_2d.h"

namespace metricmap {

/// \brief Cell values: -1 unknown, 0 free .. 100 occupied (nav_msgs/OccupancyGrid).
constexpr std::int8_t kCellUnknown = -1, kCellFree = 0, kCellOccupied = 100;

/// \brief A 2D occupancy map. Cell (i, j), i along the grid's x axis and j along its y axis,
/// spans [i r, (i + 1) r) x [j r, (j + 1) r) in the grid frame; `origin` places the grid frame
/// (its lower-left corner) in the world: world = origin * grid. Row j = 0 is the bottom row.
/// \note Plain data: const members may be called concurrently.
struct Map2D {
  int width = 0, height = 0;
  double resolution = 0.0;
  Pose2D origin;                   ///< world pose of the grid's lower-left corner (x, y, yaw)
  std::vector<std::int8_t> cells;  ///< width x height, row by row from j = 0

  bool contains(std::int64_t i, std::int64_t j) const {
    return i >= 0 && j >= 0 && i < width && j < height;
  }
  /// \brief The cell's value; kCellUnknown outside the map.
  std::int8_t at(std::int64_t i, std::int64_t j) const {
    return contains(i, j) ? cells[static_cast<std::size_t>(j * width + i)] : kCellUnknown;
  }
  /// \brief World point -> grid frame point.
  Eigen::Vector2d toGrid(const Eigen::Vector2d& world) const {
    const double c = std::cos(origin.theta), s = std::sin(origin.theta);
    const double dx = world.x() - origin.x, dy = world.y() - origin.y;
    return {c * dx + s * dy, -s * dx + c * dy};
  }
  /// \brief Grid frame point -> world point.
  Eigen::Vector2d toWorld(const Eigen::Vector2d& grid) const {
    const double c = std::cos(origin.theta), s = std::sin(origin.theta);
    return {origin.x + c * grid.x() - s * grid.y(), origin.y + s * grid.x() + c * grid.y()};
  }
  /// \brief The cell holding a world point (may be outside the map: check contains()).
  Eigen::Matrix<std::int64_t, 2, 1> worldToIndex(const Eigen::Vector2d& world) const {
    const Eigen::Vector2d g = toGrid(world) / resolution;
    return {static_cast<std::int64_t>(std::floor(g.x())),
            static_cast<std::int64_t>(std::floor(g.y()))};
  }
  /// \brief World position of the centre of cell (i, j).
  Eigen::Vector2d indexToWorld(std::int64_t i, std::int64_t j) const {
    return toWorld(
        {(static_cast<double>(i) + 0.5) * resolution, (static_cast<double>(j) + 0.5) * resolution});
  }
  /// \brief The world bounds of the map's four corners: min (x, y) and max (x, y).
  void bounds(Eigen::Vector2d& lo, Eigen::Vector2d& hi) const {
    const double w = width * resolution, h = height * resolution;
    lo = hi = toWorld({0.0, 0.0});
    for (const Eigen::Vector2d& g :
         {Eigen::Vector2d(w, 0), Eigen::Vector2d(0, h), Eigen::Vector2d(w, h)}) {
      const Eigen::Vector2d p = toWorld(g);
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
  }
};

}  // namespace metricmap
