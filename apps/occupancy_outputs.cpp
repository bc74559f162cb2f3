#include "occupancy_outputs.h"

#include "metricmap/exceptions.h"
#include "metricmap/io/cloud_writer.h"
#include "metricmap/io/map_server.h"
#include "metricmap/occupancy/octomap_quiet.h"

namespace metricmap::cli {

TrinaryMap occupancyTrinaryMap(const OccupancyOptions& o, const LogOddsMap& map,
                               const std::pair<double, double>& band) {
  if (o.out_map.empty()) return TrinaryMap();
  try {
    return projectBand(map, band.first, band.second);
  } catch (const CapacityError& e) {
    throw CapacityError("--out-map with --band " + o.band + ": " + e.what());
  }
}

void writeOccupancyOutputs(const OccupancyOptions& o, const LogOddsMap& map,
                           const TrinaryMap& trinary, OutputSet& outputs) {
  if (!o.out_bt.empty()) writeOctomapQuietly(map, outputs.stage(o.out_bt));
  if (!o.out_ot.empty()) writeOctomapQuietly(map, outputs.stage(o.out_ot));
  if (!o.out_cloud.empty())
    savePcdAtomic(outputs.stage(o.out_cloud), occupiedCenters(map), parsePcdFormat(o.pcd_format));
  if (!o.out_map.empty()) {
    MapServerFiles files = mapServerFiles(o.out_map);
    files.preview_png = o.map_preview;
    writeMapServer(mapServerImage(trinary), files, outputs);
  }
}

}  // namespace metricmap::cli
