#pragma once
/// \file module.h
/// \brief The drawing module (libmetricmap_viz.so): PNG drawings of scans, the study's charts
/// and the 3D viewer, behind plain function pointers so that a program can load it on demand
/// (dlopen) and start without VTK's rendering libraries, or link it like any library.

#include <string>
#include <vector>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include "metricmap/lines/line_segment.h"
#include "metricmap/viz/scene_types.h"
#include "metricmap/viz/study_plot.h"

namespace metricmap::viz {

/// \brief A 3D view: what to show and where (an offscreen PNG, or a window when `screenshot`
/// is empty). `point_counts` is empty or one value per point (colour_by "count").
struct ViewRequest {
  const pcl::PointCloud<pcl::PointXYZRGB>* cloud = nullptr;
  std::vector<double> point_counts;
  std::vector<CountedBox> boxes;
  std::vector<DrawnSegment> segments;
  VoxelLayer occupied;  ///< solid cubes coloured by height
  VoxelLayer free;      ///< translucent grey cubes
  SceneOptions options;
  int width = 1024, height = 768;
  std::string screenshot;
};

/// \brief Bumped whenever Module or a type it passes changes layout.
constexpr int kModuleAbi = 2;

/// \brief The module's entry points; each throws std::runtime_error naming the file it could
/// not write.
struct Module {
  int abi = kModuleAbi;
  void (*write_scan_png)(const std::string& path, const pcl::PointCloud<pcl::PointXYZ>& scan,
                         const std::vector<LineSegment>& segments) = nullptr;
  void (*write_study_plot)(const std::string& path, const std::vector<std::string>& categories,
                           const std::vector<PlotPanel>& panels) = nullptr;
  void (*show)(const ViewRequest& request) = nullptr;
};

}  // namespace metricmap::viz

/// \brief The symbol a loader looks up in libmetricmap_viz.so.
extern "C" const metricmap::viz::Module* metricmap_viz_module();
