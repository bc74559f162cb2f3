#pragma once
/// \file depth_image.h
/// \brief 16-bit depth images (PNG, TIFF) and 8-bit RGB images, read with libpng and libtiff.

#include <cstdint>
#include <string>
#include <vector>

namespace metricmap {

/// \brief Raw depth values, row-major, row 0 at the top of the picture.
struct DepthImage {
  int width = 0, height = 0;
  std::vector<std::uint16_t> values;  ///< 0 = no measurement
  std::string kind;                   ///< "png" or "tiff"
  std::uint16_t at(int u, int v) const { return values[static_cast<std::size_t>(v) * width + u]; }
};

/// \brief RGB, 3 bytes per pixel, row-major, row 0 at the top.
struct RgbImage {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;
};

/// \brief Read a single-channel 16-bit PNG or TIFF (by extension).
/// \throws InputError naming the file: unreadable, not 16-bit, more than one channel
DepthImage readDepthImage(const std::string& path);

/// \brief Read an 8-bit RGB (or RGBA: alpha dropped) PNG or TIFF.
/// \throws InputError naming the file
RgbImage readRgbImage(const std::string& path);

}  // namespace metricmap
