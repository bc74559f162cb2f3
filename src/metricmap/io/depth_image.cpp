#include "metricmap/io/depth_image.h"

#include <algorithm>
#include <cctype>

#include "metricmap/exceptions.h"
#include "metricmap/io/image_decoders.h"

namespace metricmap {
namespace {

detail::DecodedImage decode(const std::string& path, detail::ImageWant want, std::string& kind) {
  const std::size_t dot = path.find_last_of("./");
  std::string ext = dot != std::string::npos && path[dot] == '.' ? path.substr(dot + 1) : "";
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == "png") {
    kind = "png";
    return detail::decodePng(path, want);
  }
  if (ext == "tif" || ext == "tiff") {
    kind = "tiff";
    return detail::decodeTiff(path, want);
  }
  throw InputError(path + ": unknown image extension (expected .png, .tif or .tiff)");
}

}  // namespace

DepthImage readDepthImage(const std::string& path) {
  DepthImage d;
  detail::DecodedImage image = decode(path, detail::ImageWant::Depth16, d.kind);
  d.width = image.width;
  d.height = image.height;
  d.values = std::move(image.depth);
  return d;
}

RgbImage readRgbImage(const std::string& path) {
  std::string kind;
  detail::DecodedImage image = decode(path, detail::ImageWant::Rgb8, kind);
  RgbImage rgb;
  rgb.width = image.width;
  rgb.height = image.height;
  rgb.rgb = std::move(image.rgb);
  return rgb;
}

}  // namespace metricmap
