#include "slam2d_options.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "cli_common.h"
#include "metricmap/common/parse_number.h"
#include "metricmap/slam/slam_2d_parameters.h"
#include "set_options.h"

namespace metricmap::cli {
namespace {

/// --set NAME=VALUE onto the configuration: each name once, not also given by its own option,
/// no loop parameter with --no-loop-closure; the whole configuration valid.
void applySettings(const CLI::App& app, const std::vector<std::string>& settings, bool no_loops,
                   Slam2DConfig& config) {
  static const OwnOptions own = {{"map_resolution", "--map-resolution"},
                                 {"resolution", "--resolution"},
                                 {"max_range", "--max-range"},
                                 {"scans_per_submap", "--scans-per-submap"},
                                 {"loop_min_score", "--loop-min-score"},
                                 {"loop_linear_window", "--loop-window"},
                                 {"loop_angular_window_deg", "--loop-angle"}};
  const std::vector<std::string> names = applySetOptions(
      app, settings, own,
      [&config](const std::string& n, const std::string& v) { setSlam2DParameter(config, n, v); });
  for (const std::string& name : names)
    if (no_loops && isLoopClosureParameter(name))
      throw UsageError("--set " + name + " has no effect with --no-loop-closure");
  validateSetOptions([&config] { validateSlam2DConfig(config); });
}

}  // namespace

void addSlam2DOptions(CLI::App& app, Slam2DOptionValues& o) {
  const std::vector<ParameterSpec> schema = slam2DParameterSchema();
  Slam2DConfig& c = o.config;
  app.add_option("--map-resolution", c.map.resolution, "Cell of the map (m)")
      ->check(declaredRange(schema, "map_resolution"))
      ->capture_default_str();
  app.add_option("--resolution", c.resolution, "Cell of the submaps (m)")
      ->check(declaredRange(schema, "resolution"))
      ->capture_default_str();
  app.add_option("--max-range", c.max_range, "Beams beyond: free space only (m)")
      ->check(declaredRange(schema, "max_range"))
      ->capture_default_str();
  app.add_option("--scans-per-submap", c.scans_per_submap, "Nodes a submap receives")
      ->check(declaredRange(schema, "scans_per_submap"))
      ->capture_default_str();
  app.add_option("--loop-min-score", c.loop_min_score, "Score a loop closure must reach")
      ->check(declaredRange(schema, "loop_min_score"))
      ->capture_default_str();
  app.add_option("--loop-window", c.loop_linear_window, "Loop search half-width (m)")
      ->check(declaredRange(schema, "loop_linear_window"))
      ->capture_default_str();
  app.add_option("--loop-angle", c.loop_angular_window_deg, "Loop search half-angle (deg)")
      ->check(declaredRange(schema, "loop_angular_window_deg"))
      ->capture_default_str();
  app.add_option("--set", o.set,
                 "Any SLAM parameter, NAME=VALUE (repeatable; names in docs/SLAM.md)");
  app.add_flag("--no-loop-closure", o.no_loops, "Local SLAM only (no loop search)");
}

void applySlam2DOptions(const CLI::App& app, Slam2DOptionValues& o) {
  for (const char* opt : {"--loop-min-score", "--loop-window", "--loop-angle"})
    refuseIgnored(app, opt, !o.no_loops, "with --no-loop-closure");
  applySettings(app, o.set, o.no_loops, o.config);
  if (o.config.max_range <= o.config.min_range)
    throw UsageError("--max-range must exceed the minimum range");
}

}  // namespace metricmap::cli
