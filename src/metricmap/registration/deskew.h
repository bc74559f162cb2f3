#pragma once
/// \file deskew.h
/// \brief Motion correction within a sweep under the constant-velocity model, and sweep times
/// of a spinning LiDAR from the azimuth.

#include <vector>

#include <Eigen/Geometry>

namespace metricmap {

/// \brief Points moved to where they would be had the sensor not moved during the sweep.
///
/// `times` are the points' instants as fractions of the frame period (0 = sweep start, 1 = its
/// end); `motion` is the sensor's motion over one frame period (previous pose^-1 * pose). A point
/// taken at time s is moved by exp((s - reference) log(motion)), i.e. expressed in the sensor
/// frame at time `reference`.
/// \throws std::invalid_argument when `times` has another size than `points` or a non-finite value
std::vector<Eigen::Vector3d> deskewScan(const std::vector<Eigen::Vector3d>& points,
                                        const std::vector<double>& times,
                                        const Eigen::Isometry3d& motion, double reference = 0.5);

/// \brief Sweep times from the azimuth of a sensor that turns clockwise seen from above (as the
/// Velodyne HDL-64E of KITTI) and starts and ends its sweep facing backwards (-x):
/// s = (pi - atan2(y, x)) / (2 pi), in [0, 1].
std::vector<double> azimuthTimes(const std::vector<Eigen::Vector3d>& points);

}  // namespace metricmap
