#include "occupancy_2d_options.h"

#include "metricmap/exceptions.h"
#include "metricmap/io/map_server.h"

namespace metricmap::cli {

void addOccupancy2DOptions(CLI::App& app, Occupancy2DOptions& o) {
  app.add_option("--out-occupancy-2d", o.out,
                 "2D log-odds occupancy grid (beams cast in the map plane, OctoMap's sensor "
                 "model) as a map_server map: M.pgm + M.yaml")
      ->check(kOutputFile);
  app.add_option("--occupancy-2d-image", o.image,
                 "trinary (occupied 0, free 254, unknown 205) or probability (255 (1 - p), "
                 "unknown 127; YAML mode scale)")
      ->check(CLI::IsMember({"trinary", "probability"}))
      ->capture_default_str();
  app.add_option("--occupancy-2d-resolution", o.resolution, "Cell of the 2D grid (m)")
      ->check(finiteIn(1e-3, 100))
      ->capture_default_str();
  app.add_option("--band-2d", o.band,
                 "MIN,MAX: 3D points at these heights above the sensor (m, along up) are cast; "
                 "2D laser scans lie at 0")
      ->expected(2)
      ->delimiter(',')
      ->check(kFinite)
      ->capture_default_str();
  app.add_option("--occupancy-2d-max-range", o.max_range,
                 "Beams longer than this mark free space up to it and no hit (m; default none)")
      ->check(finiteIn(1e-3, 1e4));
}

void checkOccupancy2DOptions(const CLI::App& app, const Occupancy2DOptions& o) {
  const bool on = !o.out.empty();
  for (const char* option : {"--occupancy-2d-image", "--occupancy-2d-resolution", "--band-2d",
                             "--occupancy-2d-max-range"}) {
    refuseIgnored(app, option, on, "without --out-occupancy-2d");
  }
  if (o.band.size() != 2 || !(o.band[0] <= o.band[1])) {
    throw CLI::ValidationError("--band-2d", "must be MIN,MAX with MIN <= MAX");
  }
  requireExtension("--out-occupancy-2d", o.out, {".pgm"}, "a map_server PGM with its YAML");
}

RolePaths occupancy2DOutputs(const Occupancy2DOptions& o) {
  if (o.out.empty()) return {};
  const MapServerFiles f = mapServerFiles(o.out);
  return {{"--out-occupancy-2d", f.pgm}, {"--out-occupancy-2d (its .yaml)", f.yaml}};
}

std::optional<Occupancy2DConfig> occupancy2DConfig(const Occupancy2DOptions& o) {
  if (o.out.empty()) return std::nullopt;
  Occupancy2DConfig c;
  c.params.resolution = o.resolution;
  if (o.max_range) c.params.max_range = *o.max_range;
  c.band_min = o.band.at(0);
  c.band_max = o.band.at(1);
  return c;
}

nlohmann::json writeOccupancy2D(const ScanMapper& maps, const Occupancy2DOptions& o,
                                OutputSet& outputs) {
  const LogOddsGrid2D* grid = maps.occupancy2D();
  if (o.out.empty() || grid == nullptr) return nullptr;
  if (grid->knownCells() == 0) {
    throw InputError("the 2D occupancy grid is empty: no point fell within --band-2d");
  }
  const MapServerImage image =
      o.image == "probability" ? grid->probabilityImage() : grid->trinaryImage();
  MapServerFiles files = mapServerFiles(o.out);
  files.preview_png.clear();
  writeMapServer(image, files, outputs);
  return {{"width", image.width},
          {"height", image.height},
          {"resolution", image.resolution},
          {"known_cells", grid->knownCells()},
          {"occupied_cells", grid->occupiedCells()},
          {"free_cells", grid->freeCells()},
          {"image", o.image}};
}

}  // namespace metricmap::cli
