// Uses only metricmap::mapping (and core): a room scanned in memory, mapped in 2D and 3D with
// the log-odds sensor model, and registered by the odometry; each result is
// checked against what the geometry says.
#include <cmath>
#include <iostream>
#include <vector>

#include <metricmap/mapping/log_odds_grid_2d.h>
#include <metricmap/occupancy/log_odds_map.h>
#include <metricmap/registration/lidar_odometry.h>

namespace {

// A 3D scan of a box room 20.1 x 12.1 x 4 m from `at`: one ray per direction, the first wall hit.
pcl::PointCloud<pcl::PointXYZ> scanRoom(const Eigen::Vector3d& at) {
  pcl::PointCloud<pcl::PointXYZ> out;
  const Eigen::Vector3d lo(-8, -5, -1.5), hi(12.1, 7.1, 2.5);
  for (int e = -30; e <= 30; e += 2)
    for (int a = 0; a < 360; a += 1) {
      const double el = e * M_PI / 180, az = a * M_PI / 180;
      const Eigen::Vector3d d(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az),
                              std::sin(el));
      double t = 1e9;
      for (int k = 0; k < 3; ++k) {
        if (d[k] > 1e-9) t = std::min(t, (hi[k] - at[k]) / d[k]);
        if (d[k] < -1e-9) t = std::min(t, (lo[k] - at[k]) / d[k]);
      }
      const Eigen::Vector3d p = t * d;  // in the sensor frame
      out.push_back(pcl::PointXYZ(static_cast<float>(p.x()), static_cast<float>(p.y()),
                                  static_cast<float>(p.z())));
    }
  return out;
}

int fail(const char* what) {
  std::cerr << "mapping consumer: " << what << "\n";
  return 1;
}

}  // namespace

int main() {
  // 2D: one beam from (0.3, 0.3) to the wall at x = 12.1: cells 1..47 free, 48 occupied.
  metricmap::LogOddsParams p2;
  p2.resolution = 0.25;
  metricmap::LogOddsGrid2D grid(p2);
  grid.insertScan({0.3f, 0.3f}, {{12.1f, 0.3f}});
  for (int i = 1; i < 48; ++i)
    if (grid.state(i, 1) != metricmap::CellState::Free) return fail("2D: a crossed cell not free");
  if (grid.state(48, 1) != metricmap::CellState::Occupied) return fail("2D: the end not occupied");
  if (grid.knownCells() != 48) return fail("2D: cells beyond the beam");

  // 3D: the room from its middle; the wall voxel a beam ends in is occupied.
  metricmap::LogOddsParams p3;
  p3.resolution = 0.2;
  metricmap::LogOddsMap map(p3);
  pcl::PointCloud<pcl::PointXYZ> scan = scanRoom(Eigen::Vector3d::Zero());
  map.insertScan(scan, Eigen::Vector3f::Zero());
  const metricmap::VoxelKey wall{static_cast<std::int64_t>(std::floor(12.1 / 0.2)), 0, 0};
  const auto wall_l = map.logOdds(wall);
  if (!wall_l || !map.isOccupied(*wall_l)) return fail("3D: the wall ahead is not occupied");
  const auto free_l = map.logOdds({10, 0, 0});
  if (!free_l || map.isOccupied(*free_l)) return fail("3D: the room's middle is not free");

  // Odometry: the same scan twice stays where it is.
  metricmap::LidarOdometryConfig c;
  c.min_range = 0.5;
  c.max_range = 30;
  c.voxel_size = 0.3;
  metricmap::LidarOdometry odometry(c);
  odometry.registerFrame(scan);
  const metricmap::OdometryResult r = odometry.registerFrame(scan);
  const double err = r.pose.translation().norm();
  if (!(err < 1e-3)) return fail("odometry: a repeated scan moved");
  std::cout << "mapping consumer: 2D " << grid.knownCells() << " cells, 3D " << map.knownVoxels()
            << " voxels, odometry error " << err << " m\n";
  return 0;
}
