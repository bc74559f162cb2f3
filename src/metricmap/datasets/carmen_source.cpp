#include "metricmap/datasets/carmen_source.h"

#include <cmath>
#include <stdexcept>

#include "metricmap/common/memory_budget.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/carmen_log.h"

namespace metricmap {
namespace {

Eigen::Isometry3d isometry(const Pose2D& p) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translation() = Eigen::Vector3d(p.x, p.y, 0.0);
  t.linear() = Eigen::AngleAxisd(p.theta, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return t;
}

}  // namespace

CarmenSource::CarmenSource(const std::string& path) {
  info_.kind = "carmen";
  info_.path = path;
  info_.planar = true;
  CarmenLogReader reader(path);
  CarmenLaser m;
  bool all_stamped = true, all_robot_laser = true;
  std::vector<double> stamps;
  while (reader.next(m)) {
    if (lines_.empty() && m.robot_laser && m.odometry && m.laser_pose) {
      info_.sensor_to_base = isometry(*m.odometry).inverse() * isometry(*m.laser_pose);
    }
    all_robot_laser = all_robot_laser && m.robot_laser && m.odometry && m.laser_pose;
    all_stamped = all_stamped && std::isfinite(m.stamp);
    checkMemory(lines_.size() + 1, sizeof(std::size_t) + sizeof(double),
                path + ": index of " + std::to_string(lines_.size() + 1) + " scans");
    lines_.push_back(m.line);
    stamps.push_back(m.stamp);
  }
  skipped_lines_ = reader.skippedLines();
  odometry_lines_ = reader.odometryLines();
  if (lines_.empty()) {
    throw InputError(path + ": no FLASER or ROBOTLASER1 scan found" +
                     (skipped_lines_
                          ? " (" + std::to_string(skipped_lines_) + " malformed scan lines skipped)"
                          : std::string()));
  }
  if (!all_robot_laser) info_.sensor_to_base = Eigen::Isometry3d::Identity();
  if (skipped_lines_ > 0) {
    warnings_.push_back(path + ": skipped " + std::to_string(skipped_lines_) +
                        " malformed scan line(s)");
  }
  if (all_stamped) {
    info_.stamps = std::move(stamps);
  } else {
    warnings_.push_back(path + ": some scan lines have no time stamp: the source has none");
  }
}

CarmenSource::~CarmenSource() = default;

Scan CarmenSource::scan(std::size_t i) {
  if (i >= lines_.size()) {
    throw InputError(info_.path + ": no scan " + std::to_string(i) + " (" +
                     std::to_string(lines_.size()) + " scans, numbered from 0)");
  }
  if (!reader_ || i < next_) {
    reader_.reset();  // the old one is closed before the file is opened again
    reader_ = std::make_unique<CarmenLogReader>(info_.path);
    next_ = 0;
  }
  reader_->skipTo(lines_[i]);
  CarmenLaser m;
  if (!reader_->next(m) || m.line != lines_[i]) {
    reader_.reset();
    throw InputError(info_.path + ": line " + std::to_string(lines_[i]) +
                     ": no longer the scan it was when the log was opened (file changed?)");
  }
  next_ = i + 1;
  Scan s;
  s.points = scanToCloud(m.scan);
  s.laser = std::move(m.scan);
  s.stamp = m.stamp;
  if (m.odometry) s.odometry = isometry(*m.odometry);
  s.index = i;
  s.name = info_.path + ": line " + std::to_string(m.line);
  return s;
}

std::unique_ptr<ScanSource> openCarmenSource(const std::string& path) {
  return std::make_unique<CarmenSource>(path);
}

}  // namespace metricmap
