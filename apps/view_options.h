#pragma once
/// \file view_options.h
/// \brief The options of `metricmap view`, their checks, and what they say about the inputs.

#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "metricmap/occupancy/octomap_io.h"
#include "metricmap/viz/view_content.h"

namespace metricmap::cli {

struct ViewOptions {
  std::vector<std::string> files;
  bool octree = false, grid = false, show_empty = false, free = false;
  long long max_points = 100;
  float min_cell_size = 1.0f, cell_size = 1.0f;
  std::string color_by = "height", screenshot, window_size = "1280x800", camera = "iso", up = "z";
  std::string segments, preset;
  long long scan = 0;
};

/// \brief An OctoMap file (.bt, .ot), by its name.
bool isOctomapFile(const std::string& f);

/// \brief A scan log (.csv angle,range; CARMEN; --preset logs): drawn as a 2D cloud at z = 0.
bool isScanLog(const std::string& f, const ViewOptions& o);

/// \brief What drawing an OctoMap's voxels as cubes costs (with free voxels: `with_free`).
OctomapUse cubeUse(bool with_free);

/// \brief Options that would have no effect on this view are refused, never dropped:
/// usage errors (exit 2).
void refuseIgnoredViewOptions(const ViewOptions& o, const CLI::App& app);

/// \brief The structures --octree and --grid draw, with their settings.
viz::StructureSettings structureSettings(const ViewOptions& o);

/// \brief --window-size WxH (16 to 16384 each). \throws CLI::ValidationError
std::pair<int, int> parseWindowSize(const std::string& text);

/// \brief Every OctoMap file's voxels, expanded and drawn, within the memory budget: checked
/// from the trees' leaves before anything is expanded or a window opened.
void checkOctomapBudget(const ViewOptions& o);

}  // namespace metricmap::cli
