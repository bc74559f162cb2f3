// map_server maps loaded as Map2D: cells against map_server's rules written out in the test, a
// round trip through the toolkit's own writer, and one clear error for each hostile file.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

#include "metricmap/common/memory_budget.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/map_server.h"
#include "metricmap/io/map_server_reader.h"
#include "metricmap/mapping/log_odds_grid_2d.h"
#include "temp_dir.h"

namespace {

using metricmap::CapacityError;
using metricmap::InputError;
using metricmap::Map2D;

std::string yamlText(const std::string& image, const std::string& extra = "",
                     const std::string& negate = "0") {
  return "image: " + image + "\nresolution: 0.5\norigin: [1.0, -2.0, 0.0]\nnegate: " + negate +
         "\noccupied_thresh: 0.65\nfree_thresh: 0.196\n" + extra;
}

void writeBytes(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

/// map_server's value of one grey pixel, written out plainly (ROS map_server image_loader).
int expected(int grey, bool negate, const std::string& mode) {
  if (negate) grey = 255 - grey;
  if (mode == "raw") return grey <= 100 ? grey : -1;
  const double occ = (255.0 - grey) / 255.0;
  if (occ > 0.65) return 100;
  if (occ < 0.196) return 0;
  if (mode == "trinary") return -1;
  return static_cast<int>(99.0 * (occ - 0.196) / (0.65 - 0.196));
}

/// A 3 x 2 binary PGM: rows top to bottom.
const std::string kPixels = std::string("\x00\xfe\xcd", 3) + std::string("\x80\xff\x30", 3);

TEST(MapServerReader, CellsFollowMapServerRulesInEveryMode) {
  TempDir dir("mapread_modes");
  writeBytes(dir / "m.pgm", "P5\n# comment\n3 2\n255\n" + kPixels);
  for (const std::string mode : {"trinary", "scale", "raw"})
    for (const bool negate : {false, true}) {
      const std::string yaml =
          dir.write("m.yaml", yamlText("m.pgm", "mode: " + mode + "\n", negate ? "1" : "0"));
      const Map2D map = metricmap::loadMapServer(yaml);
      ASSERT_EQ(map.width, 3);
      ASSERT_EQ(map.height, 2);
      for (int row = 0; row < 2; ++row)
        for (int i = 0; i < 3; ++i) {
          const int grey =
              static_cast<unsigned char>(kPixels[static_cast<std::size_t>(row * 3 + i)]);
          EXPECT_EQ(map.at(i, 1 - row), expected(grey, negate, mode))
              << mode << " negate " << negate << " pixel " << row << "," << i;
        }
    }
}

TEST(MapServerReader, PlainPgmEqualsBinaryAndPlacesCellsInTheWorld) {
  TempDir dir("mapread_plain");
  writeBytes(dir / "b.pgm", "P5 3 2 255 " + kPixels);
  std::string plain = "P2\n3 2\n255\n";
  for (char c : kPixels) plain += std::to_string(static_cast<unsigned char>(c)) + " ";
  writeBytes(dir / "p.pgm", plain);
  const Map2D b = metricmap::loadMapServer(dir.write("b.yaml", yamlText("b.pgm")));
  const Map2D p = metricmap::loadMapServer(dir.write("p.yaml", yamlText(dir / "p.pgm")));
  EXPECT_EQ(b.cells, p.cells);
  // origin (1, -2), 0.5 m cells: cell (2, 1) spans x [2, 2.5), y [-1.5, -1).
  const Eigen::Vector2d c = b.indexToWorld(2, 1);
  EXPECT_DOUBLE_EQ(c.x(), 2.25);
  EXPECT_DOUBLE_EQ(c.y(), -1.25);
  EXPECT_EQ(b.worldToIndex({2.01, -1.49}), (Eigen::Matrix<std::int64_t, 2, 1>(2, 1)));
  Eigen::Vector2d lo, hi;
  b.bounds(lo, hi);
  EXPECT_DOUBLE_EQ(lo.x(), 1.0);
  EXPECT_DOUBLE_EQ(hi.y(), -1.0);
}

TEST(MapServerReader, YawTurnsTheGridAboutItsOrigin) {
  TempDir dir("mapread_yaw");
  writeBytes(dir / "m.pgm", "P5 3 2 255 " + kPixels);
  const Map2D map = metricmap::loadMapServer(
      dir.write("m.yaml",
                "image: m.pgm\nresolution: 1\norigin: [10, 20, 1.5707963267948966]\nnegate: "
                "0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n"));
  // Grid x points along world y: cell (2, 0)'s centre (2.5, 0.5) is at world (9.5, 22.5).
  const Eigen::Vector2d w = map.indexToWorld(2, 0);
  EXPECT_NEAR(w.x(), 9.5, 1e-12);
  EXPECT_NEAR(w.y(), 22.5, 1e-12);
  EXPECT_EQ(map.worldToIndex(w), (Eigen::Matrix<std::int64_t, 2, 1>(2, 0)));
}

TEST(MapServerReader, RoundTripThroughTheWriterKeepsEveryCellState) {
  metricmap::LogOddsParams params;
  params.resolution = 0.1;
  metricmap::LogOddsGrid2D grid(params);
  std::vector<Eigen::Vector2f> ends;
  for (int k = 0; k < 60; ++k) {
    const double a = k * 0.1;
    ends.emplace_back(static_cast<float>(2.0 * std::cos(a)), static_cast<float>(1.5 * std::sin(a)));
  }
  grid.insertScan({0.3f, 0.1f}, ends);
  TempDir dir("mapread_roundtrip");
  metricmap::writeMapServer(grid.trinaryImage(), metricmap::mapServerFiles(dir / "g.pgm"));
  const Map2D map = metricmap::loadMapServer(dir / "g.yaml");
  std::size_t occupied = 0, free = 0;
  for (std::int64_t j = grid.minJ() - 1; j <= grid.minJ() + grid.height(); ++j)
    for (std::int64_t i = grid.minI() - 1; i <= grid.minI() + grid.width(); ++i) {
      // The cell's centre, found through the map's world -> index.
      const auto ij = map.worldToIndex({(i + 0.5) * 0.1, (j + 0.5) * 0.1});
      const std::int8_t v = map.at(ij.x(), ij.y());
      switch (grid.state(i, j)) {
        case metricmap::CellState::Occupied:
          EXPECT_EQ(v, 100);
          ++occupied;
          break;
        case metricmap::CellState::Free:
          EXPECT_EQ(v, 0);
          ++free;
          break;
        case metricmap::CellState::Unknown:
          EXPECT_EQ(v, -1);
          break;
      }
    }
  EXPECT_EQ(occupied, grid.occupiedCells());
  EXPECT_EQ(free, grid.freeCells());
}

/// The error message of loading `yaml`, checked to be one line naming `names`.
template <typename Error>
std::string errorOf(const std::string& yaml, const std::string& names) {
  try {
    metricmap::loadMapServer(yaml);
  } catch (const Error& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find(names), std::string::npos) << m;
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
    return m;
  }
  ADD_FAILURE() << yaml << " loaded";
  return "";
}

TEST(MapServerReader, HostileFilesGetOneClearError) {
  TempDir dir("mapread_hostile");
  writeBytes(dir / "ok.pgm", "P5 3 2 255 " + kPixels);
  EXPECT_NE(errorOf<InputError>(dir.write("a.yaml", yamlText("missing.pgm")), "missing.pgm")
                .find("cannot open"),
            std::string::npos);
  writeBytes(dir / "huge.pgm", "P5 100000 100000 255 " + kPixels);
  EXPECT_NE(errorOf<InputError>(dir.write("b.yaml", yamlText("huge.pgm")), "huge.pgm")
                .find("100000 x 100000"),
            std::string::npos);
  writeBytes(dir / "wide.pgm", "P5 99999999 1 255 " + kPixels);
  errorOf<InputError>(dir.write("c.yaml", yamlText("wide.pgm")), "wide.pgm");
  writeBytes(dir / "deep.pgm", "P5 3 2 65535 " + kPixels + kPixels);
  errorOf<InputError>(dir.write("d.yaml", yamlText("deep.pgm")), "16-bit");
  writeBytes(dir / "text.pgm", "hello, not an image");
  errorOf<InputError>(dir.write("e.yaml", yamlText("text.pgm")), "not a PGM");
  writeBytes(dir / "short.pgm", "P2 3 2 255 1 2 3");
  errorOf<InputError>(dir.write("f.yaml", yamlText("short.pgm")), "short.pgm");
  errorOf<InputError>(dir.write("g.yaml", yamlText(dir.path.string())), "not a regular file");
  errorOf<InputError>(dir.write("h.yaml", "image: ok.pgm\n"), "'resolution'");
  errorOf<InputError>(dir.write("i.yaml", yamlText("ok.pgm", "mode: fuzzy\n")), "mode");
  errorOf<InputError>(dir.write("j.yaml",
                                "image: ok.pgm\nresolution: nan\norigin: [0, 0, 0]\nnegate: 0\n"
                                "occupied_thresh: 0.65\nfree_thresh: 0.196\n"),
                      "resolution");
  errorOf<InputError>(dir.write("k.yaml",
                                "image: ok.pgm\nresolution: 0.05\norigin: [0, 0]\nnegate: 0\n"
                                "occupied_thresh: 0.65\nfree_thresh: 0.196\n"),
                      "origin");
  errorOf<InputError>(dir.write("l.yaml",
                                "image: ok.pgm\nresolution: 0.05\norigin: [0, 0, 0]\nnegate: 0\n"
                                "occupied_thresh: 0.1\nfree_thresh: 0.9\n"),
                      "thresh");
  errorOf<InputError>(dir.write("m.yaml", "image: [ok.pgm\n"), "m.yaml");
  errorOf<InputError>(dir.write("n.yaml", "- just\n- a list\n"), "n.yaml");
  errorOf<InputError>(dir / "absent.yaml", "absent.yaml");
  // Within the side limit but beyond the budget: refused before allocating.
  const std::uint64_t budget = metricmap::memoryBudget();
  metricmap::setMemoryBudget(1000);
  writeBytes(dir / "big.pgm", "P5 100 100 255 " + std::string(10000, '\xfe'));
  errorOf<CapacityError>(dir.write("o.yaml", yamlText("big.pgm")), "big.pgm");
  metricmap::setMemoryBudget(budget);
}

}  // namespace
