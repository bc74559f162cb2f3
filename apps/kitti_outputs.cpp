#include "kitti_outputs.h"

#include "cli_common.h"
#include "metricmap/common/parse_number.h"
#include "metricmap/io/cloud_writer.h"
#include "metricmap/io/map_server.h"
#include "metricmap/io/trajectory.h"
#include "metricmap/occupancy/occupancy_export.h"
#include "metricmap/occupancy/octomap_quiet.h"

namespace metricmap::cli {

void checkKittiOutputs(const KittiOptions& o, const std::vector<std::size_t>& frames) {
  std::vector<std::pair<std::string, std::string>> outputs = {{"--out-poses", o.out_poses},
                                                              {"--out-cloud", o.out_cloud}};
  if (!o.out_map.empty()) {
    const MapServerFiles files = mapServerFiles(o.out_map);
    outputs.insert(outputs.end(), {{"--out-map", files.pgm},
                                   {"--out-map (its .yaml)", files.yaml},
                                   {"--out-map (its _preview.png)", files.preview_png},
                                   {"--out-map (its _heat.png)", files.heat_png}});
  }
  if (!o.out_octomap.empty()) outputs.push_back({"--out-octomap", o.out_octomap});
  if (!o.out_trinary.empty()) {
    const MapServerFiles files = mapServerFiles(o.out_trinary);
    outputs.insert(outputs.end(),
                   {{"--out-trinary", files.pgm}, {"--out-trinary (its .yaml)", files.yaml}});
  }
  requireDistinctFiles(kittiInputs(o.root, o.sequence, frames, o.poses != "odometry"), outputs);
  requireExtension("--out-cloud", o.out_cloud, {".pcd"}, "a PCD cloud");
  requireExtension("--out-map", o.out_map, {".pgm"}, "a map_server PGM with its YAML");
  requireExtension("--out-poses", o.out_poses, {".txt"}, "KITTI pose text");
  requireExtension("--out-octomap", o.out_octomap, {".bt", ".ot"}, "an OctoMap file");
  requireExtension("--out-trinary", o.out_trinary, {".pgm"}, "a map_server PGM with its YAML");
}

void writeKittiOutputs(const KittiOptions& o, const KittiMappingRun& run, const MapImage& image,
                       const pcl::PointCloud<pcl::PointXYZ>& global, OutputSet& outputs) {
  if (!o.out_poses.empty()) {
    writeTextAtomic(outputs.stage(o.out_poses), formatKittiPoses(run.posesOfScans()));
  }
  if (!o.out_cloud.empty()) {
    savePcdAtomic(outputs.stage(o.out_cloud), global, parsePcdFormat(o.pcd_format));
  }
  const LogOddsMap* occupancy = run.mapper->occupancy();
  if (!o.out_octomap.empty()) writeOctomapQuietly(*occupancy, outputs.stage(o.out_octomap));
  if (!o.out_trinary.empty()) {
    const std::vector<double> band = parseDoubleList(o.band, "--band");
    const TrinaryMap t = projectBand(*occupancy, band.at(0), band.at(1));
    MapServerFiles files = mapServerFiles(o.out_trinary);
    files.preview_png.clear();
    writeMapServer(mapServerImage(t), files, outputs);
  }
  if (!o.out_map.empty()) {
    writeMapServer(mapServerImage(image, run.mapper->config().min_hits), mapServerFiles(o.out_map),
                   outputs, heatImage(image));
  }
}

}  // namespace metricmap::cli
