#pragma once
/// \file image_decoders.h
/// \brief PNG (libpng) and TIFF (libtiff) decoders that turn every codec error into InputError and
/// check the declared size against the file and the memory budget before allocating.

#include <cstdint>
#include <string>
#include <vector>

namespace metricmap {
namespace detail {

/// \brief What the caller needs from the image.
enum class ImageWant { Depth16, Rgb8 };

/// \brief A decoded image, row 0 at the top; `depth` (Depth16) or `rgb` (Rgb8, 3 bytes a pixel).
struct DecodedImage {
  int width = 0, height = 0;
  std::vector<std::uint16_t> depth;
  std::vector<std::uint8_t> rgb;
};

/// \throws InputError naming the file (unreadable, damaged, wrong layout); CapacityError (budget)
DecodedImage decodePng(const std::string& path, ImageWant want);

/// \throws InputError naming the file (unreadable, damaged, wrong layout); CapacityError (budget)
DecodedImage decodeTiff(const std::string& path, ImageWant want);

}  // namespace detail
}  // namespace metricmap
