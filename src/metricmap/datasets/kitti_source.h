#pragma once
/// \file kitti_source.h
/// \brief The KITTI odometry layout as a scan source: sequences/NN/velodyne/NNNNNN.bin,
/// calib.txt's Tr as the extrinsic, times.txt as stamps, poses/NN.txt (camera 0) as the
/// reference, given as velodyne poses in the velodyne frame of frame 0 (Tr^-1 P Tr).

#include <memory>
#include <string>

#include "metricmap/datasets/scan_source.h"

namespace metricmap {

/// \brief True when `root/sequences` is a directory.
bool looksLikeKittiRoot(const std::string& root);

/// \brief The sequence `options.sequence` under `root`. size() is one more than the highest
/// frame number present; a missing frame below it is an InputError when read.
/// \throws InputError naming the file: no velodyne folder, no frame, a bad calib.txt, a bad
/// or short times.txt, a malformed pose file
std::unique_ptr<ScanSource> openKittiSource(const std::string& root,
                                            const ScanSourceOptions& options);

}  // namespace metricmap
