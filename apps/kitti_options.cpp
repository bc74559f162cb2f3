#include "kitti_options.h"

#include <limits>

#include "cli_common.h"
#include "metricmap/common/parse_number.h"

namespace metricmap::cli {
namespace {

std::vector<std::size_t> selectFrames(const KittiOptions& o) {
  if (!o.frames.empty() && o.first >= 0) {
    throw CLI::ValidationError("frames", "give --frames or --first/--count, not both");
  }
  if (o.frames.empty() && (o.first < 0 || o.count <= 0)) {
    throw CLI::ValidationError("frames", "give --frames LIST or --first F --count N (N > 0)");
  }
  if (o.frames.empty() && static_cast<unsigned long long>(o.count) > kMaxFrameList) {
    throw CLI::ValidationError("--count", "at most " + std::to_string(kMaxFrameList) + " frames");
  }
  if (!o.frames.empty()) return parseFramesOption(o.frames);
  try {
    return parseFrameList(std::to_string(o.first) + "-" + std::to_string(o.first + o.count - 1));
  } catch (const std::invalid_argument& e) {
    throw CLI::ValidationError("--first", e.what());
  }
}

/// Largest --perturb: 100 m (a pose error no registration could undo) and 180 degrees (any
/// turn); beyond them a perturbed pose is not a physical one (1e308 m leaves the float range).
constexpr double kMaxPerturbMetres = 100.0, kMaxPerturbDegrees = 180.0;

/// Translation (m) and rotation (degrees) of --perturb T,R.
std::vector<double> perturbation(const std::string& text) {
  std::vector<double> v = parseDoubleList(text, "perturbation");
  if (v.size() != 2 || !(v[0] >= 0.0 && v[0] <= kMaxPerturbMetres) ||
      !(v[1] >= 0.0 && v[1] <= kMaxPerturbDegrees)) {
    throw std::invalid_argument(
        "--perturb: expected T,R with 0 <= T <= 100 (m) and 0 <= R <= "
        "180 (degrees), got '" +
        quoteForMessage(text) + "'");
  }
  return v;
}

ScanMapperConfig mapperConfig(const KittiOptions& o, KittiWorld world) {
  ScanMapperConfig c = o.mapper;
  // The world's up axis: -y for KITTI's camera frame, z for the velodyne frame.
  c.up = world == KittiWorld::Camera ? Eigen::Vector3f(0, -1, 0) : Eigen::Vector3f(0, 0, 1);
  c.plane = parseMapPlane(o.map_plane);
  c.min_hits = static_cast<std::uint32_t>(o.min_hits);
  c.keep_global_cloud = !o.out_cloud.empty();
  c.registration.enabled = !o.refine.empty();
  if (c.registration.enabled) c.registration.refine.method = parseRefineMethod(o.refine);
  c.registration.target = parseRegistrationTarget(o.refine_target);
  c.odometry = o.poses == "odometry";
  if (o.occupancy_resolution > 0.0) {
    LogOddsParams p;
    p.resolution = o.occupancy_resolution;
    p.max_range = o.occupancy_max_range;
    c.occupancy = p;
  } else if (!o.out_octomap.empty() || !o.out_trinary.empty()) {
    throw CLI::ValidationError("--occupancy-resolution",
                               "--out-octomap and --out-trinary need the 3D occupancy map");
  }
  if (!o.out_trinary.empty() && world != KittiWorld::Velodyne) {
    throw CLI::ValidationError("--out-trinary", "the band is along z: needs --world velodyne");
  }
  if (o.out_trinary.empty() != o.band.empty()) {
    throw CLI::ValidationError("--band", "--out-trinary and --band go together");
  }
  try {
    validateScanMapperConfig(c);
  } catch (const std::invalid_argument& e) {
    throw CLI::ValidationError(e.what());  // option values: a usage error
  }
  return c;
}

/// Options that would have no effect in this run are refused, never dropped.
void refuseIgnoredOptions(const KittiOptions& o, const CLI::App& app) {
  const bool perturbs = !o.perturb.empty() && perturbation(o.perturb) != std::vector<double>{0, 0};
  refuseIgnored(
      app, "--seed", perturbs,
      "without --perturb T,R (T or R > 0): it seeds the perturbation's random directions");
  refuseIgnored(app, "--refine-target", !o.refine.empty(),
                "without --refine icp|gicp: it is what a refined scan is aligned to");
  refuseIgnored(app, "--target-voxel", !o.refine.empty() && o.refine_target == "map",
                "without --refine icp|gicp --refine-target map: it is the cell of the "
                "accumulated registration target");
  refuseIgnored(app, "--pcd-format", !o.out_cloud.empty(),
                "without --out-cloud: it is the encoding of the PCD written there");
  refuseIgnored(app, "--occupancy-max-range", o.occupancy_resolution > 0.0,
                "without --occupancy-resolution: it cuts the beams of the 3D occupancy map");
  refuseIgnored(app, "--occupancy-resolution",
                !o.out_octomap.empty() || !o.out_trinary.empty() || o.format == "json",
                "without --out-octomap, --out-trinary or --format json: the 3D map would be "
                "built and shown nowhere");
  refuseIgnored(app, "--count", o.frames.empty(),
                "with --frames: it counts frames from --first; give --frames or --first/--count");
  // The range and height windows, named as given (`1e2`, not `100.000000`).
  const auto quoted = [&app](const char* option, double value) {
    const std::string text = givenText(app, option);
    return std::string(option) + " '" + (text.empty() ? plainNumber(value) : text) + "'";
  };
  const ScanMapperConfig& m = o.mapper;
  if (m.min_range > m.max_range) {
    throw UsageError(quoted("--min-range", m.min_range) + " exceeds " +
                     quoted("--max-range", m.max_range) +
                     ": no return lies between the min range and the max range");
  }
  if (m.min_height > m.max_height) {
    throw UsageError(quoted("--min-height", m.min_height) + " exceeds " +
                     quoted("--max-height", m.max_height) +
                     ": no point lies between the min height and the max height");
  }
}

}  // namespace

const CLI::Validator kVoxelSize(
    [](std::string& s) -> std::string {
      double v = 0.0;
      try {
        v = parseFiniteDouble(s, "--voxel");
      } catch (const std::invalid_argument&) {
        return "'" + quoteForMessage(s) + "' is not a finite decimal number";
      }
      if (v < 0.0) return "must be a finite number >= 0, got '" + quoteForMessage(s) + "'";
      if (v != 0.0 &&
          !(v >= std::numeric_limits<float>::min() && v <= std::numeric_limits<float>::max()))
        return "'" + quoteForMessage(s) +
               "' is outside the single-precision range (1.2e-38 to 3.4e38)";
      return std::string();
    },
    "VOXEL");

const CLI::Validator kPerturbation(
    [](std::string& s) {
      try {
        perturbation(s);
      } catch (const std::invalid_argument& e) {
        return std::string(e.what());
      }
      return std::string();
    },
    "T,R");

const CLI::Validator kBand(
    [](std::string& s) {
      try {
        const std::vector<double> b = parseDoubleList(s, "--band");
        if (b.size() != 2 || b[0] > b[1]) return std::string("--band must be zmin,zmax");
      } catch (const std::invalid_argument& e) {
        return std::string(e.what());
      }
      return std::string();
    },
    "ZMIN,ZMAX");

KittiMappingOptions kittiMappingOptions(const KittiOptions& o, const CLI::App& app) {
  refuseIgnoredOptions(o, app);
  KittiMappingOptions m;
  m.frames = selectFrames(o);
  if (o.poses == "odometry" && !o.perturb.empty()) {
    throw CLI::ValidationError("--perturb",
                               "moves poses from the pose file; not with --poses odometry");
  }
  const std::vector<double> perturb =
      o.perturb.empty() ? std::vector<double>{0.0, 0.0} : perturbation(o.perturb);
  m.perturb_translation = perturb[0];
  m.perturb_rotation_deg = perturb[1];
  m.seed = o.seed;
  m.world = o.world == "velodyne" ? KittiWorld::Velodyne : KittiWorld::Camera;
  m.mapper = mapperConfig(o, m.world);
  m.sequence = KittiSequence{o.root, o.sequence};
  return m;
}

}  // namespace metricmap::cli
