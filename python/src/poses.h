#pragma once
/// \file poses.h
/// \brief Trajectories and pose lists <-> numpy: (N, 4, 4) float64 arrays of rigid transforms,
/// (N,) stamps, (N, 3) planar poses (x, y, theta).

#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "arrays.h"
#include "metricmap/common/map_server_image.h"
#include "metricmap/common/pose_2d.h"
#include "metricmap/common/trajectory.h"

namespace metricmap::python {

/// \brief Poses as a new (N, 4, 4) float64 array.
py::array_t<double> posesArray(const std::vector<Eigen::Isometry3d>& poses);

/// \brief An (N, 4, 4) array of finite rigid transforms (rotation orthonormal with det +1 to
/// 1e-3; last row 0 0 0 1 to 1e-6) as poses. `allow_empty`: N = 0 accepted.
/// \throws py::value_error naming `name` and the first bad pose; py::type_error for a
/// non-numeric dtype
std::vector<Eigen::Isometry3d> posesFrom(const py::handle& obj, const char* name,
                                         bool allow_empty = false);

/// \brief An (N, 3) array of finite planar poses x, y, theta (`allow_single`: a (3,) one too).
/// \throws py::value_error naming `name` and the first bad pose
std::vector<Pose2D> planarPosesFrom(const py::handle& obj, const char* name,
                                    bool allow_single = false);

/// \brief Poses given as (N, 4, 4) rigid transforms or (N, 3) planar poses (x, y, theta, as
/// 3D poses at z = 0).
std::vector<Eigen::Isometry3d> spatialOrPlanarPosesFrom(const py::handle& obj, const char* name);

/// \brief A 1-D array of `n` finite stamps (seconds). \throws py::value_error
std::vector<double> stampsFrom(const py::handle& obj, const char* name, std::size_t n);

/// \brief Doubles as a new (N,) float64 array.
py::array_t<double> doublesArray(const std::vector<double>& values);

/// \brief Planar poses as a new (N, 3) float64 array of x (m), y (m), theta (rad).
py::array_t<double> poses2dArray(const std::vector<Pose2D>& poses);

/// \brief A planar pose from (3,) x, y, theta or a (4, 4) transform (its x, y and yaw).
/// \throws py::value_error for another shape or a non-finite value
Pose2D pose2dFrom(const py::handle& obj, const char* name);

/// \brief The planar part of a 3D pose: x, y and the yaw atan2(R10, R00).
Pose2D planar(const Eigen::Isometry3d& t);

/// \brief A planar pose as a 3D one (z = 0, rotation about z).
Eigen::Isometry3d spatial(const Pose2D& p);

/// \brief Frame indices (a 1-D sequence or iterable of non-negative integers) or None -> empty
/// vector (the library's "every scan"). \throws py::value_error for an empty selection, which
/// would otherwise mean every scan
std::vector<std::size_t> framesFrom(const py::object& obj, const char* name);

/// \brief The scans a run function processes: `frames` as framesFrom reads it, each below
/// `size` and strictly increasing; None selects every scan. \throws py::value_error otherwise
std::vector<std::size_t> selectedFrames(const py::object& frames, std::size_t size);

/// \brief A map_server image as a dict: image (H, W) uint8 (row 0 at the top), resolution,
/// origin (x, y of the lower-left corner), mode.
py::dict mapServerDict(const MapServerImage& image);

/// \brief Write `image` as map_server files: `path` (.pgm) and the .yaml beside it, each
/// through a temporary file and a rename. \throws py::value_error unless `path` ends in .pgm
void writeMapImage(const std::string& path, const MapServerImage& image);

}  // namespace metricmap::python
