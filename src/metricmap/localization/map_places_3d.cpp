#include "metricmap/localization/map_places_3d.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "metricmap/common/memory_budget.h"
#include "metricmap/localization/place_descriptor_3d.h"

namespace metricmap {
namespace {

/// A grid of `edge` cells over the map's x/y bounds.
struct Grid {
  double x0 = 0, y0 = 0, edge = 1;
  long nx = 0, ny = 0;
  Grid(const Eigen::AlignedBox3d& b, double e) : x0(b.min().x()), y0(b.min().y()), edge(e) {
    nx = static_cast<long>(std::floor((b.max().x() - x0) / e)) + 1;
    ny = static_cast<long>(std::floor((b.max().y() - y0) / e)) + 1;
  }
  long ix(double x) const { return std::clamp(static_cast<long>((x - x0) / edge), 0L, nx - 1); }
  long iy(double y) const { return std::clamp(static_cast<long>((y - y0) / edge), 0L, ny - 1); }
  std::size_t cells() const { return static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny); }
};

constexpr float kEmpty = std::numeric_limits<float>::infinity();

}  // namespace

std::vector<MapPlace3D> buildMapPlaces(const PointMap3D& map, const Localizer3DConfig& c) {
  const Grid fine(map.bounds, c.place_cell), coarse(map.bounds, c.place_spacing);
  const double fine_cells = double(fine.nx) * double(fine.ny);
  checkMemory(fine_cells > 1e15 ? std::uint64_t{1} << 50 : std::uint64_t(fine_cells),
              2 * sizeof(float),
              "the map's height image (" + std::to_string(fine.nx) + " x " +
                  std::to_string(fine.ny) + " cells of " + std::to_string(c.place_cell) + " m)");
  std::vector<float> low(fine.cells(), kEmpty), high(fine.cells(), -kEmpty);
  for (const Eigen::Vector3f& p : map.points) {
    const std::size_t k =
        std::size_t(fine.iy(p.y())) * std::size_t(fine.nx) + std::size_t(fine.ix(p.x()));
    low[k] = std::min(low[k], p.z());
    high[k] = std::max(high[k], p.z());
  }
  // Each place's ground: the median of its cells' lowest points.
  std::vector<float> ground(coarse.cells(), kEmpty);
  {
    std::vector<std::vector<float>> lows(coarse.cells());
    for (long j = 0; j < fine.ny; ++j)
      for (long i = 0; i < fine.nx; ++i) {
        const float z = low[std::size_t(j) * std::size_t(fine.nx) + std::size_t(i)];
        if (z == kEmpty) continue;
        const double x = fine.x0 + (double(i) + 0.5) * fine.edge;
        const double y = fine.y0 + (double(j) + 0.5) * fine.edge;
        lows[std::size_t(coarse.iy(y)) * std::size_t(coarse.nx) + std::size_t(coarse.ix(x))]
            .push_back(z);
      }
    for (std::size_t k = 0; k < lows.size(); ++k) {
      auto& v = lows[k];
      if (v.empty()) continue;
      std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
      ground[k] = v[v.size() / 2];
    }
  }
  std::vector<int> on_ground(coarse.cells(), 0), blocked(coarse.cells(), 0);
  for (const Eigen::Vector3f& p : map.points) {
    const std::size_t k =
        std::size_t(coarse.iy(p.y())) * std::size_t(coarse.nx) + std::size_t(coarse.ix(p.x()));
    if (ground[k] == kEmpty) continue;
    const double h = double(p.z()) - ground[k];
    if (std::fabs(h) <= 0.3) ++on_ground[k];
    if (h > 0.5 && h < c.place_clearance) ++blocked[k];
  }
  PlaceDescriptorParams dp{c.descriptor, c.clip_height, c.clip_slope};
  const double radius = c.descriptor.max_radius;
  const long reach = static_cast<long>(std::ceil(radius / fine.edge));
  std::vector<MapPlace3D> places;
  std::vector<Eigen::Vector3f> relative;
  for (long j = 0; j < coarse.ny; ++j)
    for (long i = 0; i < coarse.nx; ++i) {
      const std::size_t k = std::size_t(j) * std::size_t(coarse.nx) + std::size_t(i);
      if (ground[k] == kEmpty || on_ground[k] < c.place_min_ground_points ||
          blocked[k] > std::max(2, on_ground[k] / 50))
        continue;
      const double px = coarse.x0 + (double(i) + 0.5) * coarse.edge;
      const double py = coarse.y0 + (double(j) + 0.5) * coarse.edge;
      relative.clear();
      const long ci = fine.ix(px), cj = fine.iy(py);
      for (long b = std::max(0L, cj - reach); b <= std::min(fine.ny - 1, cj + reach); ++b)
        for (long a = std::max(0L, ci - reach); a <= std::min(fine.nx - 1, ci + reach); ++a) {
          const float top = high[std::size_t(b) * std::size_t(fine.nx) + std::size_t(a)];
          if (top == -kEmpty) continue;
          const float dx = static_cast<float>(fine.x0 + (double(a) + 0.5) * fine.edge - px);
          const float dy = static_cast<float>(fine.y0 + (double(b) + 0.5) * fine.edge - py);
          relative.emplace_back(dx, dy, top - ground[k]);
        }
      places.push_back({Eigen::Vector3d(px, py, ground[k]), placeDescriptor(relative, dp)});
    }
  return places;
}

}  // namespace metricmap
