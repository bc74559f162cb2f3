#pragma once
/// \file occupancy_map_2d.h
/// \brief 2D hit-count map by projection onto a plane, and its map_server form.

#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include "metricmap/common/map_server_image.h"

namespace metricmap {

/// \brief Projection plane: the image's x and y axes are these world axes. For xz the image's
/// x is world x and its y is world z; rows run from the top, so row 0 holds the largest z.
enum class MapPlane { XZ, XY, YZ };

/// \brief "xz" | "xy" | "yz". \throws std::invalid_argument
MapPlane parseMapPlane(const std::string& name);

/// \brief A dense view of the map: hits per pixel, row 0 at the top; origin is the world
/// position (along the plane's two axes) of the lower-left corner of the lower-left pixel.
struct MapImage {
  int width = 0, height = 0;
  double resolution = 0.0;
  double origin_x = 0.0, origin_y = 0.0;
  std::vector<std::uint32_t> hits;
  std::uint32_t at(int col, int row) const {
    return hits[static_cast<std::size_t>(row) * width + col];
  }
};

/// \brief Counts hits per cell of `resolution` on the plane; grows with the data (sparse cells).
/// \note Thread safety: one instance per thread.
class OccupancyMap2D {
 public:
  /// \throws std::invalid_argument for a resolution that is not finite and > 0
  OccupancyMap2D(double resolution, MapPlane plane);
  /// \brief Count every finite point (already in the world frame).
  /// \throws CapacityError when a cell index leaves the 32-bit range (resolution too fine)
  void add(const pcl::PointCloud<pcl::PointXYZ>& world_points);
  /// \brief Cells with at least one hit.
  std::size_t cells() const { return hits_.size(); }
  /// \brief Cells with at least `min_hits` hits (and at least one).
  std::size_t occupied(std::uint32_t min_hits) const;
  /// \brief The dense image over the hit cells' bounds (empty map: 0 x 0).
  /// \throws CapacityError when it would exceed `max_pixels` pixels
  MapImage image(std::uint64_t max_pixels = kMaxImagePixels) const;
  /// \brief Default bound of image(): 2^28 pixels (1 GiB of hit counts).
  static constexpr std::uint64_t kMaxImagePixels = std::uint64_t{1} << 28;

 private:
  double resolution_;
  MapPlane plane_;
  std::unordered_map<std::uint64_t, std::uint32_t> hits_;
};

/// \brief The map as map_server reads it (io/map_server.h writes it): occupied (0, black) where
/// hits >= min_hits (and >= 1), free (254) elsewhere; the YAML's mode unstated (trinary).
/// \throws std::invalid_argument for an empty map
MapServerImage mapServerImage(const MapImage& map, std::uint32_t min_hits);

/// \brief A heat map of the hits (RGB, row-major, log scale; black where no hit).
std::vector<std::uint8_t> heatImage(const MapImage& map);

}  // namespace metricmap
