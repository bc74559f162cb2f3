#pragma once
/// \file camera_intrinsics.h
/// \brief Pinhole intrinsics from flags, PCL grabber XML, Open3D camera JSON or a field of view.

#include <string>

namespace metricmap {

/// \brief fx, fy, cx, cy in pixels; depth_scale metres per raw unit (0 when the source has none).
struct CameraIntrinsics {
  double fx = 0, fy = 0, cx = 0, cy = 0;
  int width = 0, height = 0;  ///< 0 when the source does not say
  double depth_scale = 0.0;
};

/// \brief "fx,fy,cx,cy". \throws std::invalid_argument
CameraIntrinsics parseIntrinsics(const std::string& text);

/// \brief The <depth> block of a PCL image-grabber XML (focal lengths, principal point,
/// z_multiplication_factor). \throws InputError naming the file
CameraIntrinsics readPclGrabberXml(const std::string& path);

/// \brief Open3D PinholeCameraIntrinsic JSON: width, height and a column-major
/// "intrinsic_matrix" (fx = m[0], fy = m[4], cx = m[6], cy = m[7]). \throws InputError
CameraIntrinsics readOpen3dJson(const std::string& path);

/// \brief Square pixels from a horizontal field of view: f = (W/2) / tan(hfov/2), principal
/// point at the image centre (W/2, H/2). \throws std::invalid_argument
CameraIntrinsics intrinsicsFromHfov(double hfov_deg, int width, int height);

/// \brief Reads .xml as PCL grabber XML and .json as Open3D JSON. \throws InputError
CameraIntrinsics readCameraFile(const std::string& path);

/// \throws std::invalid_argument unless fx, fy > 0 and everything is finite
void validateIntrinsics(const CameraIntrinsics& k);

}  // namespace metricmap
