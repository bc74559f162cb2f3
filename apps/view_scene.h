#pragma once
/// \file view_scene.h
/// \brief The viewer's VTK scene: points coloured by height, rgb or count, octree leaves or grid
/// cells as one wireframe vtkPolyData coloured by point count, a title and a colour bar.

#include <string>
#include <vector>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <vtkSmartPointer.h>
#include <Eigen/Core>

class vtkRenderer;
class vtkActor;

namespace metricmap::cli {

/// \brief An axis-aligned box with the number of points it holds.
struct CountedBox {
  Eigen::Vector3d min, max;
  double count = 0;
};

struct SceneOptions {
  std::string title;
  std::string color_by = "height";  ///< height | rgb | count
  int up_axis = 2;                  ///< 0 x, 1 y, 2 z
  std::string camera = "iso";       ///< top | side | iso
};

/// \brief The assembled scene; `points` and `boxes` can be toggled.
struct Scene {
  vtkSmartPointer<vtkRenderer> renderer;
  vtkSmartPointer<vtkActor> points;
  vtkSmartPointer<vtkActor> boxes;  ///< null without boxes
};

/// \brief A 2D segment to draw at z = 0 (from `metricmap lines --format json`).
struct DrawnSegment {
  Eigen::Vector2d start, end;
};

/// \brief Build the scene. `point_counts` (same length as the cloud, or empty) colours points
/// by the count of their cell when color_by is "count".
Scene buildScene(const pcl::PointCloud<pcl::PointXYZRGB>& cloud,
                 const std::vector<double>& point_counts, const std::vector<CountedBox>& boxes,
                 const SceneOptions& options, const std::vector<DrawnSegment>& segments = {});

/// \brief Render offscreen at width x height and write a PNG (through a temporary file).
/// \throws std::runtime_error naming the file
void writeScreenshot(const Scene& scene, int width, int height, const std::string& path);

/// \brief Open an interactive window (h: help, p: points, c: cubes, r: reset view, q: quit).
void runInteractive(const Scene& scene, int width, int height);

}  // namespace metricmap::cli
