#pragma once
/// \file map_sinks.h
/// \brief The map sinks of the mapping pipeline: the 2D hit map, the 2D log-odds grid, the 3D
/// log-odds map and the global cloud.

#include <cstdint>
#include <limits>

#include "metricmap/mapping/log_odds_grid_2d.h"
#include "metricmap/mapping/map_sink.h"
#include "metricmap/mapping/occupancy_map_2d.h"
#include "metricmap/occupancy/log_odds_map.h"

namespace metricmap {

/// \brief 2D hit counts in the map plane of the (voxel-averaged) points whose height along
/// `up` lies in [min_height, max_height]; insert returns the points counted.
class HitMapSink : public MapSink {
 public:
  HitMapSink(double resolution, MapPlane plane, const Eigen::Vector3f& up, double min_height,
             double max_height);
  std::uint64_t insert(const SinkScan& scan) override;
  const OccupancyMap2D& map() const { return map_; }

 private:
  OccupancyMap2D map_;
  Eigen::Vector3f up_;
  double min_height_, max_height_;
};

/// \brief 2D log-odds grid in the map plane: the points within [band_min, band_max] of the
/// sensor's height (along `up`), projected onto the plane and cast from the sensor's projected
/// position; insert returns the beams cast.
class LogOddsGrid2DSink : public MapSink {
 public:
  LogOddsGrid2DSink(const LogOddsParams& params, MapPlane plane, const Eigen::Vector3f& up,
                    double band_min, double band_max);
  std::uint64_t insert(const SinkScan& scan) override;
  const LogOddsGrid2D& grid() const { return grid_; }

 private:
  LogOddsGrid2D grid_;
  MapPlane plane_;
  Eigen::Vector3f up_;
  double band_min_, band_max_;
};

/// \brief 3D log-odds map: every point of the scan as given (no range band) cast from the
/// sensor's position; insert returns the points cast.
class LogOddsMapSink : public MapSink {
 public:
  explicit LogOddsMapSink(const LogOddsParams& params);
  std::uint64_t insert(const SinkScan& scan) override;
  const LogOddsMap& map() const { return map_; }

 private:
  LogOddsMap map_;
};

/// \brief The registered scans in the world (voxel-averaged points appended); insert returns
/// the points appended.
class GlobalCloudSink : public MapSink {
 public:
  explicit GlobalCloudSink(double voxel);
  std::uint64_t insert(const SinkScan& scan) override;
  /// \brief The cloud, averaged again in `voxel` cells when voxel > 0.
  pcl::PointCloud<pcl::PointXYZ> cloud() const;

 private:
  double voxel_;
  pcl::PointCloud<pcl::PointXYZ> cloud_;
};

/// \brief `cloud` averaged in world-aligned cells of `voxel` (OccupancyGrid, WorldAligned).
pcl::PointCloud<pcl::PointXYZ> voxelAverage(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                                            double voxel);

}  // namespace metricmap
