// metricmap kitti ROOT --sequence NN: scans + poses -> global cloud and a 2D occupancy map.
#include <cstdio>
#include <limits>
#include <memory>

#include <unistd.h>

#include "cli_common.h"
#include "commands.h"
#include "kitti_options.h"
#include "kitti_outputs.h"
#include "kitti_report.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/output_set.h"

namespace metricmap::cli {
namespace {

void run(const KittiOptions& o, const CLI::App& app) {
  const auto t_start = std::chrono::steady_clock::now();
  const KittiMappingOptions m = kittiMappingOptions(o, app);
  checkKittiOutputs(o, m.frames);
  const bool progress = isatty(STDERR_FILENO) != 0;
  const KittiMappingRun r =
      mapKittiSequence(m, [&](std::size_t done, std::size_t total, const KittiMappingTotals& tot) {
        if (!progress) return;
        const double elapsed = secondsSince(t_start);
        std::fprintf(stderr, "\rframe %zu/%zu  %.1f M points/s  %.0f s left   ", done, total,
                     static_cast<double>(tot.points_read) / elapsed / 1e6,
                     elapsed / static_cast<double>(done) * static_cast<double>(total - done));
      });
  if (progress) std::fprintf(stderr, "\n");

  const auto t = std::chrono::steady_clock::now();
  const MapImage image = r.mapper->map().image();
  if (!o.out_map.empty() && image.width == 0) {
    throw InputError("the map is empty: no point fell within the range and height bands");
  }
  requireOccupiedCells(image, static_cast<std::uint32_t>(o.min_hits), o.out_map);
  const pcl::PointCloud<pcl::PointXYZ> global = r.mapper->globalCloud();
  OutputSet outputs;  // every output or none, committed once the report is printed
  writeKittiOutputs(o, r, image, global, outputs);
  const KittiReportFigures figures{global.size(), secondsSince(t), secondsSince(t_start)};
  emit(kittiReport(o, m, r, image, figures), outputs);
}

}  // namespace

void addKittiCommand(CLI::App& app) {
  auto o = std::make_shared<KittiOptions>();
  ScanMapperConfig& m = o->mapper;
  o->min_hits = m.min_hits;
  CLI::App* sub =
      app.add_subcommand("kitti", "KITTI scans + poses -> global cloud, 2D occupancy map");
  sub->add_option("root", o->root, "KITTI odometry root (sequences/, poses/)")->required();
  sub->add_option("--sequence", o->sequence, "Sequence number")->capture_default_str();
  sub->add_option("--frames", o->frames, "Frames, e.g. 0-5,15");
  sub->add_option("--first", o->first, "First frame")->check(kCount);
  sub->add_option("--count", o->count, "Number of frames")->check(kCount);
  sub->add_option("--world", o->world, "camera (KITTI's, y down) or velodyne (z up)")
      ->check(CLI::IsMember({"camera", "velodyne"}))
      ->capture_default_str();
  sub->add_option("--min-range", m.min_range, "Drop returns closer than this (m), e.g. the car")
      ->check(kFiniteNonNegative)
      ->capture_default_str();
  sub->add_option("--max-range", m.max_range, "Drop returns further than this (m)")
      ->check(kFinitePositive);
  sub->add_option("--min-height", m.min_height, "Map only points at or above this height (m)")
      ->check(kFinite);
  sub->add_option("--max-height", m.max_height, "Map only points at or below this height (m)")
      ->check(kFinite);
  sub->add_option("--voxel", m.voxel, "Per-scan and global voxel size (m), 0: off")
      ->check(kVoxelSize)
      ->capture_default_str();
  sub->add_option("--out-cloud", o->out_cloud, "Write the global cloud (.pcd)")->check(kOutputFile);
  addPcdFormatOption(*sub, o->pcd_format);
  sub->add_option("--out-map", o->out_map,
                  "map_server map: M.pgm + M.yaml, with M_preview.png and M_heat.png")
      ->check(kOutputFile);
  sub->add_option("--map-plane", o->map_plane, "Projection plane")
      ->check(CLI::IsMember({"xz", "xy", "yz"}))
      ->capture_default_str();
  sub->add_option("--map-resolution", m.map_resolution, "Map cell size (m), 0.0001 to 1000")
      ->check(kCellEdge)
      ->capture_default_str();
  sub->add_option("--min-hits", o->min_hits, "Hits that make a cell occupied")
      ->check(countIn(1, std::numeric_limits<std::uint32_t>::max()))
      ->capture_default_str();
  sub->add_option("--refine", o->refine,
                  "Align each scan to --refine-target (pcl::IterativeClosestPoint or "
                  "pcl::GeneralizedIterativeClosestPoint), starting from its pose")
      ->check(CLI::IsMember({"icp", "gicp"}));
  sub->add_option("--refine-target", o->refine_target,
                  "map: the refined scans so far; previous: the last scan; first: frame 0 only")
      ->check(CLI::IsMember({"map", "previous", "first"}))
      ->capture_default_str();
  sub->add_option("--target-voxel", m.registration.target_voxel,
                  "Cell of the accumulated registration target (m)")
      ->check(kFinitePositiveFloat)
      ->capture_default_str();
  sub->add_option("--out-poses", o->out_poses,
                  "Write the poses used (refined, perturbed or given), one 3x4 row-major line "
                  "per frame as in poses/NN.txt (velodyne poses with --world velodyne)")
      ->check(kOutputFile);
  sub->add_option("--perturb", o->perturb,
                  "t,r: move each pose after frame 0 by t metres and turn it by r degrees, "
                  "random directions (seeded)")
      ->check(kPerturbation);
  sub->add_option("--seed", o->seed, "Random seed for --perturb")
      ->check(countIn(0, std::numeric_limits<unsigned>::max()))
      ->capture_default_str();
  sub->add_option("--poses", o->poses,
                  "file: poses/NN.txt; odometry: from the scans (LidarOdometry), no pose file "
                  "needed (--refine still applies on top)")
      ->check(CLI::IsMember({"file", "odometry"}))
      ->capture_default_str();
  sub->add_option("--occupancy-resolution", o->occupancy_resolution,
                  "Also build the 3D log-odds occupancy map (ray casting, OctoMap's model) with "
                  "voxels of this size (m), 0.0001 to 1000")
      ->check(kCellEdge);
  sub->add_option("--occupancy-max-range", o->occupancy_max_range,
                  "Beams longer than this are cut there and mark no hit (m)")
      ->check(kFinitePositive)
      ->capture_default_str();
  sub->add_option("--out-octomap", o->out_octomap, "Write the 3D map: .bt or .ot (OctoMap)")
      ->check(kOutputFile);
  sub->add_option("--out-trinary", o->out_trinary,
                  "Trinary map_server map (M.pgm + M.yaml) of the 3D map's --band (z, velodyne "
                  "world): occupied 0, free 254, unknown 205")
      ->check(kOutputFile);
  sub->add_option("--band", o->band, "zmin,zmax of --out-trinary (m)")->check(kBand);
  addFormatOption(*sub, o->format, {"table", "json"});
  sub->callback([o, sub] { run(*o, *sub); });
}

}  // namespace metricmap::cli
