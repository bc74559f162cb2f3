// Distance fields as OpenVDB files, read back by OpenVDB itself (the oracle for its format):
// every voxel of the box holds the field's value at the world position the field gives it,
// points outside the box read the clamp, and a bad volume, path or budget is refused whole.
#include <gtest/gtest.h>

#include <openvdb/openvdb.h>

#include <cstdio>
#include <filesystem>
#include <random>
#include <stdexcept>
#include <string>

#include "metricmap/common/memory_budget.h"
#include "metricmap/distance/distance_field.h"
#include "metricmap/distance/distance_volume.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/vdb_writer.h"

namespace metricmap {
namespace {

OccupancyBox box(int dims, std::array<std::size_t, 3> shape, unsigned seed) {
  OccupancyBox b;
  b.dimensions = dims;
  b.shape = shape;
  b.resolution = 0.25;
  b.origin = Eigen::Vector3d(-3.125, 10.375, dims == 3 ? 0.625 : 0.0);
  b.state.resize(b.voxels());
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  for (auto& s : b.state) {
    const double r = u(rng);
    s = r < 0.03 ? kVoxelOccupied : (r < 0.1 ? kVoxelUnknown : kVoxelFree);
  }
  return b;
}

std::string tempPath(const std::string& name) {
  return (std::filesystem::temp_directory_path() /
          ("metricmap_vdb_" + std::to_string(::getpid()) + "_" + name))
      .string();
}

openvdb::FloatGrid::Ptr readBack(const std::string& path) {
  openvdb::initialize();
  openvdb::io::File f(path);
  f.open();
  openvdb::FloatGrid::Ptr g = openvdb::gridPtrCast<openvdb::FloatGrid>(f.readGrid("distance"));
  f.close();
  return g;
}

void expectSameField(const DistanceField& field, const std::string& path) {
  const openvdb::FloatGrid::Ptr g = readBack(path);
  ASSERT_TRUE(g);
  EXPECT_EQ(g->background(), static_cast<float>(field.params().max_distance));
  EXPECT_EQ(g->getGridClass(),
            field.params().signed_distance ? openvdb::GRID_LEVEL_SET : openvdb::GRID_UNKNOWN);
  const auto acc = g->getConstAccessor();
  const auto& s = field.shape();
  const std::size_t nz = field.dimensions() == 3 ? s[2] : 1;
  std::size_t active = 0;
  for (std::size_t i = 0; i < s[0]; ++i)
    for (std::size_t j = 0; j < s[1]; ++j)
      for (std::size_t k = 0; k < nz; ++k) {
        const openvdb::Coord c{static_cast<int>(i), static_cast<int>(j), static_cast<int>(k)};
        const float want = field.field()[(i * s[1] + j) * nz + k];
        ASSERT_EQ(acc.getValue(c), want) << i << " " << j << " " << k;
        active += acc.isValueOn(c);
        const openvdb::Vec3d w = g->indexToWorld(c);
        const Eigen::Vector3d centre =
            field.origin() + field.resolution() * Eigen::Vector3d(double(i), double(j), double(k));
        ASSERT_NEAR(w.x(), centre.x(), 1e-9);
        ASSERT_NEAR(w.y(), centre.y(), 1e-9);
        ASSERT_NEAR(w.z(), centre.z(), 1e-9);
      }
  EXPECT_EQ(active, std::size_t(g->activeVoxelCount()));  // nothing stored outside the box
  EXPECT_EQ(acc.getValue(openvdb::Coord(-1, 0, 0)), g->background());
  EXPECT_EQ(acc.getValue(openvdb::Coord(int(s[0]) + 5, 0, 0)), g->background());
  EXPECT_LT(active, field.voxels());  // voxels at the clamp are left out (sparse)
}

TEST(VdbWriter, A3DFieldReadsBackVoxelForVoxel) {
  DistanceFieldParams p;
  p.max_distance = 0.6;
  const DistanceField field(box(3, {23, 17, 9}, 1), p);
  const std::string path = tempPath("3d.vdb");
  writeVdb(path, vdbVolumeOf(field));
  expectSameField(field, path);
  std::remove(path.c_str());
}

TEST(VdbWriter, ASigned2DFieldIsALevelSetLayer) {
  DistanceFieldParams p;
  p.max_distance = 0.8;
  p.signed_distance = true;
  const DistanceField field(box(2, {31, 12, 1}, 2), p);
  const std::string path = tempPath("2d.vdb");
  writeVdb(path, vdbVolumeOf(field));
  expectSameField(field, path);
  std::remove(path.c_str());
}

TEST(VdbWriter, BadVolumesPathsAndBudgetsAreRefused) {
  DistanceFieldParams p;
  p.max_distance = 0.5;
  const DistanceField field(box(3, {8, 8, 8}, 3), p);
  VdbVolume v = vdbVolumeOf(field);
  VdbVolume wrong = v;
  wrong.shape[0] = 9;  // more voxels than values
  EXPECT_THROW(writeVdb(tempPath("x.vdb"), wrong), std::invalid_argument);
  wrong = v;
  wrong.resolution = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(writeVdb(tempPath("x.vdb"), wrong), std::invalid_argument);
  try {
    writeVdb("/nonexistent-dir/x.vdb", v);
    FAIL() << "an unwritable path was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent-dir/x.vdb"), std::string::npos) << e.what();
  }
  const std::uint64_t saved = memoryBudget();
  setMemoryBudget(1000);  // 512 voxels at 5 bytes: over
  EXPECT_THROW(writeVdb(tempPath("y.vdb"), v), CapacityError);
  setMemoryBudget(saved);
  EXPECT_FALSE(std::filesystem::exists(tempPath("y.vdb")));
}

}  // namespace
}  // namespace metricmap
