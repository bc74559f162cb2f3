// metricmap occupancy INPUT...: KITTI scans or PCD files (VIEWPOINT = sensor pose) cast into a
// probabilistic voxel map (LogOddsMap), written as OctoMap .bt/.ot, occupied voxel centres and
// a trinary map_server map from a height band. A .bt/.ot INPUT is read and exported instead.
// With --distributed (under mpirun) each rank casts its contiguous share of the frames or files
// and the voxels are merged over MPI (ranks.h); rank 0 writes the outputs.
#include <cstdio>
#include <iostream>
#include <memory>
#include <utility>

#include <unistd.h>

#include "cli_common.h"
#include "commands.h"
#include "metricmap/io/output_set.h"
#include "metricmap/occupancy/cast_totals.h"
#include "metricmap/occupancy/octomap_quiet.h"
#include "metricmap/sequence/sequence_mapper.h"
#include "occupancy_options.h"
#include "occupancy_outputs.h"
#include "occupancy_report.h"
#include "ranks.h"
#include "sequence_options.h"

namespace metricmap::cli {
namespace {

void castScans(const OccupancyOptions& o, OccupancyInputKind kind, const Ranks& ranks,
               LogOddsMap& map, OccupancyTotals& tot) {
  const bool progress = isatty(STDERR_FILENO) != 0 && !ranks.distributed();
  const auto t_start = std::chrono::steady_clock::now();
  const CastProgress report = [&](std::size_t done, std::size_t total) {
    if (!progress) return;
    const double elapsed = secondsSince(t_start);
    std::fprintf(stderr, "\rscan %zu/%zu  %.0f ms/scan  %.0f s left   ", done, total,
                 1000.0 * tot.insert_s / static_cast<double>(done),
                 elapsed / static_cast<double>(done) * static_cast<double>(total - done));
  };
  if (kind == OccupancyInputKind::KittiRoot) {
    if (o.frames.empty()) throw CLI::ValidationError("frames", "a KITTI root needs --frames");
    const std::vector<std::size_t> frames = parseFramesOption(o.frames);
    const auto [first, last] = ranks.share(frames.size());
    const KittiWorld world = o.world == "camera" ? KittiWorld::Camera : KittiWorld::Velodyne;
    castKittiFrames(map, KittiSequence{o.inputs[0], o.sequence}, frames, first, last, world, tot,
                    report);
  } else if (kind == OccupancyInputKind::ScanSource) {
    SourceOptions so;
    so.path = o.inputs[0];
    so.frames = o.frames;
    so.topic = o.topic;
    so.reference = o.reference;
    const std::unique_ptr<ScanSource> source = openSource(so);
    const std::vector<std::size_t> frames = selectedFrames(so, *source);
    const std::vector<Eigen::Isometry3d> poses = referenceSensorPoses(*source, frames);
    const auto [first, last] = ranks.share(frames.size());
    castSourceFrames(map, *source, frames, poses, first, last, tot, report);
  } else {
    const auto [first, last] = ranks.share(o.inputs.size());
    castPcdScans(map, o.inputs, first, last, tot, report);
  }
  if (progress) std::fprintf(stderr, "\n");
  for (const std::string& w : tot.warnings) std::cerr << "warning: " << w << "\n";
}

void run(const OccupancyOptions& o, const Ranks& ranks) {
  const OccupancyInputKind kind = occupancyInputKind(o.inputs);
  const bool from_file = kind == OccupancyInputKind::OctomapFile;
  const OccupancyPlan plan = checkOccupancyOptions(o, kind);
  OccupancyTotals tot;
  auto t = std::chrono::steady_clock::now();
  LogOddsMap map = from_file
                       ? readOctomapQuietly(o.inputs[0], LogOddsParams(), occupancyExportUse(o))
                       : LogOddsMap(plan.params);
  if (from_file) tot.load_s = secondsSince(t);
  map.setThreads(o.threads);
  if (!from_file) castScans(o, kind, ranks, map, tot);
  if (ranks.distributed()) {
    map = ranks.reduce(std::move(map));
    ScanCastTotals& cast = tot;  // the job's totals on rank 0
    cast = reduceCastTotals(tot, {[&](auto& v) { ranks.sum(v); }, [&](auto& v) { ranks.max(v); }},
                            tot.insert_cpu_s);
    if (!ranks.isRoot()) return;
  }

  // everything that can fail on the data is computed before the first file is written
  t = std::chrono::steady_clock::now();
  const TrinaryMap trinary = occupancyTrinaryMap(o, map, plan.band);
  OutputSet outputs;  // every output or none, committed once the report is printed
  writeOccupancyOutputs(o, map, trinary, outputs);
  tot.write_s = secondsSince(t);
  emit(occupancyReport(o.format, map, tot, !o.out_map.empty(), trinary), outputs);
}

}  // namespace

void addOccupancyCommand(CLI::App& app) {
  auto o = std::make_shared<OccupancyOptions>();
  CLI::App* sub = app.add_subcommand(
      "occupancy", "Ray-cast scans into a log-odds voxel map; OctoMap .bt/.ot, 2D trinary map");
  sub->add_option("input", o->inputs,
                  "A KITTI root (with --frames), a scan source cast at its reference poses (a "
                  "folder of scans with poses.txt, a .txt list, a CARMEN log; --frames "
                  "optional), PCD files (VIEWPOINT = sensor pose), or one .bt/.ot map to export")
      ->required();
  sub->add_option("--resolution", o->resolution, "Voxel edge (m), 0.0001 to 1000")
      ->check(kCellEdge);
  sub->add_option("--max-range", o->max_range, "Beams are cut here and mark no hit (m), > 0")
      ->check(kFinitePositive);
  sub->add_option("--threads", o->threads,
                  "Threads casting each scan's beams (0: all hardware threads); the map does not "
                  "depend on it")
      ->check(countIn(0, 1024))
      ->capture_default_str();
  sub->add_option("--sequence", o->sequence, "KITTI sequence")->capture_default_str();
  sub->add_option("--topic", o->topic, "Bag topic (a scan source that is a ROS bag)");
  sub->add_option("--reference", o->reference,
                  "Poses of the source's scans (KITTI or TUM rows; a bag has none of its own)");
  sub->add_option("--frames", o->frames, "KITTI or scan source frames, e.g. 0-5,15")
      ->check(CLI::Validator(
          [](std::string& s) -> std::string {
            return s.empty() ? "the frame list is empty (omit --frames for all frames)" : "";
          },
          "FRAMES"));
  sub->add_option("--world", o->world, "KITTI world: velodyne (z up) or camera (y down)")
      ->check(CLI::IsMember({"camera", "velodyne"}))
      ->capture_default_str();
  sub->add_option("--out", o->out_bt, "Write OctoMap .bt (maximum likelihood)")->check(kOutputFile);
  sub->add_option("--out-ot", o->out_ot, "Write OctoMap .ot (log-odds)")->check(kOutputFile);
  sub->add_option("--out-cloud", o->out_cloud, "Write the occupied voxel centres (.pcd)")
      ->check(kOutputFile);
  sub->add_option("--out-map", o->out_map, "Write a trinary map_server map (.pgm + .yaml)")
      ->check(kOutputFile);
  sub->add_option("--band", o->band, "Height band of --out-map: zmin,zmax (m)");
  sub->add_option("--map-preview", o->map_preview, "Also write --out-map as PNG")
      ->check(kOutputFile);
  addPcdFormatOption(*sub, o->pcd_format);
  sub->add_flag("--distributed", o->distributed,
                "Run as MPI ranks (mpirun -np N metricmap occupancy ...): each rank casts its "
                "share of the frames or files, voxels are merged by tile; rank 0 writes");
  addFormatOption(*sub, o->format, {"table", "json"});
  sub->callback([o, sub] {
    OccupancyOptions opts = *o;
    opts.resolution_given = sub->count("--resolution") > 0;
    opts.max_range_given = sub->count("--max-range") > 0;
    opts.sequence_given = sub->count("--sequence") > 0;
    opts.world_given = sub->count("--world") > 0;
    opts.threads_given = sub->count("--threads") > 0;
    opts.pcd_format_given = sub->count("--pcd-format") > 0;
    if (opts.distributed && occupancyInputKind(opts.inputs) == OccupancyInputKind::OctomapFile)
      throw UsageError("--distributed casts scans; a .bt/.ot input is exported by one process");
    const Ranks ranks(opts.distributed);
    ranks.run([&] { run(opts, ranks); });
  });
}

}  // namespace metricmap::cli
