#include "metricmap/sequence/sequence_mapper.h"

#include <stdexcept>

#include "metricmap/exceptions.h"

namespace metricmap {
namespace {

// The coordinate plane perpendicular to the up axis's largest component.
MapPlane mapPlaneOfUp(const Eigen::Vector3f& up) {
  Eigen::Index axis = 0;
  up.cwiseAbs().maxCoeff(&axis);
  return axis == 0 ? MapPlane::YZ : axis == 1 ? MapPlane::XZ : MapPlane::XY;
}

}  // namespace

MapConvention mapConvention(const SourceInfo& info) {
  MapConvention c;
  c.up = info.conventions.up;
  c.plane = mapPlaneOfUp(c.up);
  return c;
}

std::vector<Eigen::Isometry3d> referenceSensorPoses(const ScanSource& source,
                                                    const std::vector<std::size_t>& frames) {
  const SourceInfo& info = source.info();
  if (info.reference.size() < source.size()) {
    throw InputError(info.path + ": no reference poses (poses/NN.txt, poses.txt or --reference)");
  }
  const Eigen::Isometry3d a =
      info.conventions.poses_of_base ? info.sensor_to_base : Eigen::Isometry3d::Identity();
  std::vector<Eigen::Isometry3d> out;
  out.reserve(frames.size());
  for (std::size_t f : frames) out.push_back(a * info.reference.poses.at(f));
  return out;
}

std::vector<Eigen::Isometry3d> odometrySensorPoses(const OdometryRun& run, const SourceInfo& info) {
  const Eigen::Isometry3d a =
      info.conventions.poses_of_base ? info.sensor_to_base : Eigen::Isometry3d::Identity();
  std::vector<Eigen::Isometry3d> out;
  out.reserve(run.trajectory.size());
  for (const Eigen::Isometry3d& p : run.trajectory.poses) out.push_back(p * a);
  return out;
}

SequenceMapper::SequenceMapper(ScanSource& source, const ScanMapperConfig& config)
    : source_(source), config_(config) {
  validateScanMapperConfig(config_);
}

const ScanMapper& SequenceMapper::build(const std::vector<Eigen::Isometry3d>& poses,
                                        const std::vector<std::size_t>& frames,
                                        const Observer& observer) {
  std::vector<std::size_t> selected = frames;
  if (selected.empty()) {
    for (std::size_t i = 0; i < source_.size(); ++i) selected.push_back(i);
  }
  if (poses.size() != selected.size()) {
    throw std::invalid_argument(std::to_string(poses.size()) + " pose(s) for " +
                                std::to_string(selected.size()) + " frame(s)");
  }
  for (std::size_t k = 1; k < selected.size(); ++k) {
    if (selected[k] <= selected[k - 1]) {
      throw std::invalid_argument("frames must be in acquisition order without repeats");
    }
  }
  mapper_.reset();  // the old maps go before the new ones grow
  auto mapper = std::make_unique<ScanMapper>(config_);
  for (std::size_t k = 0; k < selected.size(); ++k) {
    const Scan scan = source_.scan(selected[k]);
    const FrameReport r = mapper->addScan(scan.points, poses[k]);
    if (observer) observer(r, k + 1, selected.size());
  }
  mapper_ = std::move(mapper);
  return *mapper_;
}

const ScanMapper& SequenceMapper::maps() const {
  if (!mapper_) throw std::logic_error("SequenceMapper::maps() before build()");
  return *mapper_;
}

}  // namespace metricmap
