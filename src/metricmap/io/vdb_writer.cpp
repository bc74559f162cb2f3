#include "metricmap/io/vdb_writer.h"

#include <cmath>
#include <cstdint>
#include <mutex>
#include <stdexcept>

#include <openvdb/openvdb.h>
#include <openvdb/tools/Dense.h>

#include "metricmap/common/memory_budget.h"

namespace metricmap {
namespace {

void checkVolume(const VdbVolume& v) {
  if (v.values == nullptr) throw std::invalid_argument("a VDB volume needs values");
  std::uint64_t n = 1;
  for (std::size_t s : v.shape) {
    // OpenVDB's coordinates are 32-bit signed integers
    if (s == 0 || s > (std::uint64_t(1) << 30))
      throw std::invalid_argument("a VDB volume's shape must be in 1..2^30 per axis");
    n *= s;
  }
  if (n != v.values->size())
    throw std::invalid_argument("a VDB volume holds " + std::to_string(v.values->size()) +
                                " values for " + std::to_string(n) + " voxels");
  if (!(std::isfinite(v.resolution) && v.resolution > 0))
    throw std::invalid_argument("a VDB volume's resolution must be finite and > 0");
  for (double o : v.origin)
    if (!std::isfinite(o)) throw std::invalid_argument("a VDB volume's origin must be finite");
  if (!std::isfinite(v.background))
    throw std::invalid_argument("a VDB volume's background must be finite");
}

openvdb::FloatGrid::Ptr buildGrid(const VdbVolume& v) {
  const openvdb::CoordBBox box(
      openvdb::Coord(0, 0, 0),
      openvdb::Coord(int(v.shape[0]) - 1, int(v.shape[1]) - 1, int(v.shape[2]) - 1));
  // LayoutZYX: z varies fastest, the C order of the values. copyFromDense only reads them.
  openvdb::tools::Dense<float, openvdb::tools::LayoutZYX> dense(
      box, const_cast<float*>(v.values->data()));
  openvdb::FloatGrid::Ptr grid = openvdb::FloatGrid::create(v.background);
  openvdb::tools::copyFromDense(dense, *grid, 0.0f);
  openvdb::math::Transform::Ptr xform =
      openvdb::math::Transform::createLinearTransform(v.resolution);
  xform->postTranslate(openvdb::Vec3d(v.origin[0], v.origin[1], v.origin[2]));
  grid->setTransform(xform);
  grid->setName(v.name);
  grid->setGridClass(v.level_set ? openvdb::GRID_LEVEL_SET : openvdb::GRID_UNKNOWN);
  grid->insertMeta("box_shape", openvdb::Vec3IMetadata(openvdb::Vec3i(
                                    int(v.shape[0]), int(v.shape[1]), int(v.shape[2]))));
  return grid;
}

}  // namespace

void writeVdb(const std::string& path, const VdbVolume& volume) {
  checkVolume(volume);
  // A leaf of 8^3 voxels holds 512 floats, its masks and a node: about 4.3 bytes a voxel
  // where every voxel is stored, the bound checked.
  checkMemory(volume.values->size(), 5, "the VDB grid of " + path);
  static std::once_flag init;
  std::call_once(init, [] { openvdb::initialize(); });
  const openvdb::FloatGrid::Ptr grid = buildGrid(volume);
  try {
    openvdb::io::File file(path);
    file.setCompression(openvdb::io::COMPRESS_ZIP | openvdb::io::COMPRESS_ACTIVE_MASK);
    file.write(openvdb::GridPtrVec{grid});
    file.close();
    // OpenVDB's file does not report a short write (a full disk): read the grid back whole
    openvdb::io::File check(path);
    check.open(false);
    const openvdb::GridBase::Ptr back = check.readGrid(volume.name);
    check.close();
    if (!back || back->activeVoxelCount() != grid->activeVoxelCount())
      throw std::runtime_error("the grid read back differs");
  } catch (const openvdb::Exception& e) {
    throw std::runtime_error(path + ": cannot write the VDB file (" + e.what() + ")");
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(path + ": cannot write the VDB file (" + e.what() + ")");
  }
}

}  // namespace metricmap
