#pragma once
/// \file camera_options.h
/// \brief --camera / --intrinsics / --hfov-deg / --depth-scale, shared by depth-to-cloud and
/// heightmap.

#include <string>

#include <CLI/CLI.hpp>

#include "metricmap/camera/camera_intrinsics.h"
#include "metricmap/io/depth_image.h"

namespace metricmap::cli {

struct CameraOptions {
  std::string camera_file, intrinsics;
  double hfov_deg = 0.0, depth_scale = 0.0;
};

/// \brief Adds the options; exactly one intrinsics source is required.
void addCameraOptions(CLI::App& app, CameraOptions& o);

/// \brief Intrinsics for an image of this size.
CameraIntrinsics resolveIntrinsics(const CameraOptions& o, const DepthImage& depth);

/// \brief --depth-scale if given, else the camera file's z factor, else by image kind:
/// TIFF (PCL grabber, millimetres) 0.001, PNG (TUM, 5000 per metre) 0.0002.
double resolveDepthScale(const CameraOptions& o, const CameraIntrinsics& k,
                         const DepthImage& depth);

}  // namespace metricmap::cli
