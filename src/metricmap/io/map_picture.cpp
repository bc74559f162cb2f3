#include "metricmap/io/map_picture.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace metricmap {
namespace {

struct Canvas {
  int w, h;
  std::vector<std::uint8_t>& rgb;
  void put(long x, long y, const std::uint8_t (&c)[3]) {
    if (x < 0 || y < 0 || x >= w || y >= h) return;
    std::uint8_t* p = &rgb[(static_cast<std::size_t>(y) * w + static_cast<std::size_t>(x)) * 3];
    p[0] = c[0];
    p[1] = c[1];
    p[2] = c[2];
  }
  /// A line by sampling at half-pixel steps (enough for a picture); segments far outside skip.
  void line(double x0, double y0, double x1, double y1, const std::uint8_t (&c)[3]) {
    const double n = std::ceil(2.0 * std::max(std::fabs(x1 - x0), std::fabs(y1 - y0)));
    if (!(n < 1e6)) return;
    for (double k = 0; k <= n; ++k) {
      const double t = n > 0 ? k / n : 0.0;
      put(static_cast<long>(std::floor(x0 + t * (x1 - x0))),
          static_cast<long>(std::floor(y0 + t * (y1 - y0))), c);
    }
  }
};

}  // namespace

std::vector<std::uint8_t> drawMapPicture(
    const MapServerImage& map, int scale, const std::vector<Eigen::Vector2d>& path,
    const std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>>& links) {
  if (map.width <= 0 || map.height <= 0 ||
      map.pixels.size() != static_cast<std::size_t>(map.width) * map.height)
    throw std::invalid_argument("drawMapPicture: empty or inconsistent map image");
  if (scale < 1 || scale > 8) throw std::invalid_argument("drawMapPicture: scale must be 1..8");
  const int w = map.width * scale, h = map.height * scale;
  std::vector<std::uint8_t> rgb(static_cast<std::size_t>(w) * h * 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::uint8_t v =
          map.pixels[static_cast<std::size_t>(y / scale) * map.width + x / scale];
      std::uint8_t* p = &rgb[(static_cast<std::size_t>(y) * w + x) * 3];
      p[0] = p[1] = p[2] = v;
    }
  Canvas canvas{w, h, rgb};
  const double px = scale / map.resolution;
  auto toX = [&](const Eigen::Vector2d& p) { return (p.x() - map.origin_x) * px; };
  auto toY = [&](const Eigen::Vector2d& p) { return h - (p.y() - map.origin_y) * px; };
  const std::uint8_t blue[3] = {30, 90, 230}, red[3] = {230, 30, 30};
  for (std::size_t k = 1; k < path.size(); ++k)
    canvas.line(toX(path[k - 1]), toY(path[k - 1]), toX(path[k]), toY(path[k]), blue);
  for (const auto& [a, b] : links) canvas.line(toX(a), toY(a), toX(b), toY(b), red);
  return rgb;
}

}  // namespace metricmap
