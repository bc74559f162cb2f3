#include "metricmap/mapping/height_map_images.h"

#include <algorithm>
#include <cstddef>

#include "metricmap/mapping/height_map.h"

namespace metricmap {
namespace {

// Low bins blue, middle (obstacles) red, high bins green-yellow.
constexpr std::uint8_t kPalette[][3] = {{70, 110, 220}, {220, 50, 40},  {240, 200, 40},
                                        {60, 180, 90},  {160, 90, 200}, {90, 200, 220}};

}  // namespace

HeightMapImages heightMapImages(const HeightMap& map) {
  const std::size_t n = map.size();
  HeightMapImages images;
  images.obstacles.resize(n * n);
  images.explored.resize(n * n);
  images.layers.assign(n * n * 3, 0);
  for (std::size_t r = 0; r < n; ++r) {
    for (std::size_t c = 0; c < n; ++c) {
      const std::size_t i = r * n + c;
      images.obstacles[i] = map.obstacle(r, c) ? 0 : 255;
      images.explored[i] = map.explored(r, c) ? 255 : 0;
      std::size_t best = 0;
      std::uint32_t most = 0;
      for (std::size_t b = 0; b < map.bins(); ++b) {
        if (map.count(r, c, b) > most) {
          most = map.count(r, c, b);
          best = b;
        }
      }
      if (most > 0) {
        const std::uint8_t* rgb = kPalette[best % 6];
        std::copy(rgb, rgb + 3, images.layers.begin() + static_cast<std::ptrdiff_t>(3 * i));
      }
    }
  }
  return images;
}

}  // namespace metricmap
