#pragma once
/// \file distance_sources.h
/// \brief The occupancy boxes a distance field is computed over, from each kind of map. Each
/// builder prices the box (distanceFieldBytesPerVoxel) against the memory budget before
/// allocating it.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>

#include <pcl/point_cloud.h>

#include "metricmap/common/map_2d.h"
#include "metricmap/distance/distance_field.h"

namespace metricmap {

class LogOddsMap;

/// \brief A box of a LogOddsMap in its own keys: voxels min_key + [0, shape).
struct KeyBox {
  std::array<std::int64_t, 3> min_key{{0, 0, 0}};
  std::array<std::size_t, 3> shape{{0, 0, 0}};
};

/// \brief The states of a 3D log-odds map over `box`, or over its known voxels' bounds.
/// \throws std::invalid_argument for an empty map (no box given) or an empty box;
/// CapacityError when the field would not fit the memory budget (the message gives its size)
OccupancyBox occupancyBoxOf(const LogOddsMap& map, const DistanceFieldParams& params,
                            const std::optional<KeyBox>& box = std::nullopt);

/// \brief The 2D states of a loaded map (io/map_server_reader: loadMapServer): cell (i, j)
/// occupied where the map says occupied (100), unknown where unknown (-1), free otherwise;
/// centred at origin + (i + 1/2, j + 1/2) resolution.
/// \throws std::invalid_argument for an empty map or an origin with a yaw; CapacityError (budget)
OccupancyBox occupancyBoxOf(const Map2D& map, const DistanceFieldParams& params);

/// \brief A point map: the voxels (floor(p / resolution)) holding a point are occupied, every
/// other voxel of their bounds is free (a point map has no unknown space). Non-finite points
/// are skipped.
/// \throws std::invalid_argument for a bad resolution or no finite point; CapacityError
/// (budget, or a key beyond 2^20 voxels from the origin)
OccupancyBox occupancyBoxOfPoints(const float* xyz, std::size_t stride_bytes, std::size_t count,
                                  double resolution, const DistanceFieldParams& params);

template <typename PointT>
OccupancyBox occupancyBoxOf(const pcl::PointCloud<PointT>& cloud, double resolution,
                            const DistanceFieldParams& params) {
  return occupancyBoxOfPoints(cloud.empty() ? nullptr : &cloud.points[0].x, sizeof(PointT),
                              cloud.size(), resolution, params);
}

}  // namespace metricmap
