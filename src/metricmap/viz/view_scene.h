#pragma once
/// \file view_scene.h
/// \brief The viewer's VTK scene: points coloured by height, rgb or count, octree leaves or grid
/// cells as one wireframe vtkPolyData coloured by point count, a title and a colour bar.

#include <string>
#include <vector>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <vtkSmartPointer.h>

#include "metricmap/viz/scene_types.h"

class vtkRenderer;
class vtkActor;

namespace metricmap::viz {

/// \brief The assembled scene; `points` and `boxes` can be toggled.
struct Scene {
  vtkSmartPointer<vtkRenderer> renderer;
  vtkSmartPointer<vtkActor> points;
  vtkSmartPointer<vtkActor> boxes;  ///< null without boxes
};

/// \brief Build the scene. `point_counts` (same length as the cloud, or empty) colours points
/// by the count of their cell when color_by is "count".
Scene buildScene(const pcl::PointCloud<pcl::PointXYZRGB>& cloud,
                 const std::vector<double>& point_counts, const std::vector<CountedBox>& boxes,
                 const SceneOptions& options, const std::vector<DrawnSegment>& segments = {},
                 const VoxelLayer& occupied = {}, const VoxelLayer& free = {});

/// \brief Render offscreen at width x height and write a PNG (through a temporary file).
/// \throws std::runtime_error naming the file
void writeScreenshot(const Scene& scene, int width, int height, const std::string& path);

/// \brief Open an interactive window (h: help, p: points, c: cubes, r: reset view, q: quit).
void runInteractive(const Scene& scene, int width, int height);

}  // namespace metricmap::viz
