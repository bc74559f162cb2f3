#pragma once
/// \file kitti_sequence.h
/// \brief The KITTI odometry layout: sequences/NN/velodyne/NNNNNN.bin, sequences/NN/calib.txt
/// (Tr: velodyne -> cam0), poses/NN.txt (12 numbers per line: T_world<-cam0 of frame i).

#include <cstddef>
#include <string>
#include <vector>

#include <Eigen/Geometry>

namespace metricmap {

/// \brief `Tr` of a KITTI calib.txt: velodyne -> camera 0.
/// \throws InputError naming the file when it is missing, has no Tr line, or Tr is not 12
/// finite numbers
Eigen::Isometry3d readKittiCalibTr(const std::string& calib_path);

/// \brief The first `frames` poses of a KITTI pose file (row-major 3x4 per line).
/// \throws InputError naming the file and line: too few lines, wrong count, NaN/Inf
std::vector<Eigen::Isometry3d> readKittiPoses(const std::string& poses_path, std::size_t frames);

/// \brief Most frames a frame list may name (KITTI's longest sequence has 4661).
constexpr std::size_t kMaxFrameList = 1000000;

/// \brief "0-5,15" -> 0 1 2 3 4 5 15 (ascending ranges, no duplicates needed).
/// \throws std::invalid_argument naming the bad item, or when the list names more than
/// `max_frames` frames (checked before anything is allocated)
std::vector<std::size_t> parseFrameList(const std::string& text,
                                        std::size_t max_frames = kMaxFrameList);

/// \brief Paths of one sequence under a KITTI odometry root.
struct KittiSequence {
  std::string root, sequence;
  std::string calib() const { return root + "/sequences/" + sequence + "/calib.txt"; }
  std::string poses() const { return root + "/poses/" + sequence + ".txt"; }
  std::string scan(std::size_t frame) const;
};

/// \brief Which frame the world is: camera 0 of frame 0 (KITTI's, y down) or the velodyne of
/// frame 0 (z up).
enum class KittiWorld { Camera, Velodyne };

/// \brief velodyne of frame i -> world: P_i * Tr (camera world) or Tr^-1 * P_i * Tr.
Eigen::Isometry3d kittiScanToWorld(const Eigen::Isometry3d& pose, const Eigen::Isometry3d& tr,
                                   KittiWorld world);

/// \brief The inverse of kittiScanToWorld for the pose file: a velodyne -> world pose as the
/// camera 0 pose KITTI's files hold (camera world), or unchanged (velodyne world).
Eigen::Isometry3d kittiPoseOfScan(const Eigen::Isometry3d& scan_to_world,
                                  const Eigen::Isometry3d& tr, KittiWorld world);

}  // namespace metricmap
