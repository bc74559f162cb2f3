#include "metricmap/occupancy/octomap_io.h"

#include <algorithm>
#include <fstream>
#include <iostream>
#include <iterator>
#include <limits>
#include <memory>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <vector>

#include <octomap/AbstractOcTree.h>
#include <octomap/OcTree.h>

#include "metricmap/common/memory_budget.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/checked_file.h"
#include "metricmap/io/cloud_writer.h"
#include "metricmap/io/input_file.h"
#include "metricmap/occupancy/octomap_file_check.h"

namespace metricmap {
namespace {

constexpr std::int64_t kOctoMaxVal = 32768;  // OctoMap's key of coordinate 0 (16 levels)

/// liboctomap as Debian builds it prints progress lines ("Reading octree type OcTree", "Done
/// (N nodes)") on std::cerr while it reads and writes; the library's callers did not ask for
/// them. While at least one QuietCerr lives, std::cerr (one stream per process) writes nothing.
class QuietCerr {
 public:
  QuietCerr() {
    std::lock_guard<std::mutex> lock(mutex());
    if (state().count++ == 0) state().saved = std::cerr.rdbuf(&state().null);
  }
  ~QuietCerr() {
    std::lock_guard<std::mutex> lock(mutex());
    if (--state().count == 0) std::cerr.rdbuf(state().saved);
  }
  QuietCerr(const QuietCerr&) = delete;
  QuietCerr& operator=(const QuietCerr&) = delete;

 private:
  struct NullBuffer : std::streambuf {
    int overflow(int c) override { return traits_type::not_eof(c); }
  };
  struct State {
    NullBuffer null;
    std::streambuf* saved = nullptr;
    int count = 0;
  };
  static State& state() {
    static State s;
    return s;
  }
  static std::mutex& mutex() {
    static std::mutex m;
    return m;
  }
};

bool endsWith(const std::string& s, const std::string& suffix) {
  if (s.size() < suffix.size()) return false;
  for (std::size_t i = 0; i < suffix.size(); ++i) {
    if (std::tolower(static_cast<unsigned char>(s[s.size() - suffix.size() + i])) != suffix[i])
      return false;
  }
  return true;
}

void useSensorModel(octomap::OcTree& tree, const LogOddsParams& p) {
  tree.setProbHit(p.prob_hit);
  tree.setProbMiss(p.prob_miss);
  tree.setClampingThresMin(p.clamp_min);
  tree.setClampingThresMax(p.clamp_max);
  tree.setOccupancyThres(p.occupancy_threshold);
}

std::unique_ptr<octomap::OcTree> toOcTree(const LogOddsMap& map) {
  VoxelKey lo, hi;
  auto tree = std::make_unique<octomap::OcTree>(map.resolution());
  useSensorModel(*tree, map.params());
  if (!map.keyBounds(lo, hi)) return tree;
  if (lo.x < -kOctoMaxVal || lo.y < -kOctoMaxVal || lo.z < -kOctoMaxVal || hi.x >= kOctoMaxVal ||
      hi.y >= kOctoMaxVal || hi.z >= kOctoMaxVal) {
    std::ostringstream msg;
    msg << "the map spans voxels (" << lo.x << ", " << lo.y << ", " << lo.z << ") to (" << hi.x
        << ", " << hi.y << ", " << hi.z << "); OctoMap files hold -32768..32767 per axis ("
        << 32768 * map.resolution() << " m at this resolution)";
    throw CapacityError(msg.str());
  }
  map.forEachKnown([&](const VoxelKey& k, float l) {
    const octomap::OcTreeKey key(static_cast<octomap::key_type>(k.x + kOctoMaxVal),
                                 static_cast<octomap::key_type>(k.y + kOctoMaxVal),
                                 static_cast<octomap::key_type>(k.z + kOctoMaxVal));
    tree->setNodeValue(key, l, /*lazy_eval=*/true);
  });
  tree->updateInnerOccupancy();
  tree->prune();
  return tree;
}

}  // namespace

void writeOctomap(const LogOddsMap& map, const std::string& path) {
  const bool binary = endsWith(path, ".bt");
  if (!binary && !endsWith(path, ".ot"))
    throw std::invalid_argument(outputDisplayName(path) + ": OctoMap files end in .bt or .ot");
  std::unique_ptr<octomap::OcTree> tree = toOcTree(map);
  std::ostringstream out(std::ios::binary);
  bool ok = false;
  {
    QuietCerr quiet;
    ok = binary ? tree->writeBinary(out) : tree->write(out);
  }
  if (!ok || !out)
    throw std::runtime_error(outputDisplayName(path) + ": liboctomap could not serialise the map");
  writeTextAtomic(path, out.str());
}

namespace {

std::uint64_t saturatingProduct(std::uint64_t a, std::uint64_t b) {
  if (a != 0 && b > std::numeric_limits<std::uint64_t>::max() / a)
    return std::numeric_limits<std::uint64_t>::max();
  return a * b;
}

std::uint64_t saturatingSum(std::uint64_t a, std::uint64_t b) {
  return b > std::numeric_limits<std::uint64_t>::max() - a
             ? std::numeric_limits<std::uint64_t>::max()
             : a + b;
}

/// The tree of an OctoMap file's checked bytes, read by liboctomap.
std::unique_ptr<octomap::OcTree> parseTree(const std::string& bytes, const OctomapFileInfo& info,
                                           const LogOddsParams& p, const std::string& path) {
  std::unique_ptr<octomap::OcTree> tree;
  std::istringstream in(bytes, std::ios::binary);
  {
    QuietCerr quiet;
    if (info.binary) {
      tree = std::make_unique<octomap::OcTree>(info.resolution);
      useSensorModel(*tree, p);
      if (!tree->readBinary(in)) throw InputError(path + ": liboctomap could not read the tree");
    } else {
      std::unique_ptr<octomap::AbstractOcTree> any(octomap::AbstractOcTree::read(in));
      auto* oc = dynamic_cast<octomap::OcTree*>(any.get());
      if (oc == nullptr) throw InputError(path + ": liboctomap could not read an OcTree");
      any.release();
      tree.reset(oc);
    }
  }
  return tree;
}

/// What the tree's leaves expand to: a leaf at depth d covers 8^(16 - d) voxels; a leaf of 8^3
/// voxels or more tiles its own blocks, smaller leaves share theirs (counted once through
/// their sorted block keys). \throws CapacityError past `max_voxels`
OctomapExpansion countExpansion(const octomap::OcTree& tree, const LogOddsMap& map,
                                std::size_t max_voxels, const std::string& path) {
  std::size_t total = 0, blocks = 0, occupied = 0;
  std::vector<std::uint64_t> small_leaf_blocks;
  const unsigned max_depth = tree.getTreeDepth();
  for (auto it = tree.begin_leafs(), end = tree.end_leafs(); it != end; ++it) {
    const unsigned levels = max_depth - it.getDepth();
    if (levels >= 10) throw CapacityError(path + ": a leaf covers more than 2^30 voxels");
    total += std::size_t{1} << (3 * levels);
    if (map.isOccupied(it->getLogOdds())) occupied += std::size_t{1} << (3 * levels);
    if (levels >= 3) {
      blocks += std::size_t{1} << (3 * (levels - 3));
    } else {
      const octomap::OcTreeKey key = it.getIndexKey();
      small_leaf_blocks.push_back((std::uint64_t{key[0]} >> 3) << 26 |
                                  (std::uint64_t{key[1]} >> 3) << 13 |
                                  (std::uint64_t{key[2]} >> 3));
    }
    if (total > max_voxels) {
      throw CapacityError(path + ": expanding the pruned leaves gives more than " +
                          std::to_string(max_voxels) + " voxels");
    }
  }
  std::sort(small_leaf_blocks.begin(), small_leaf_blocks.end());
  blocks += static_cast<std::size_t>(
      std::unique(small_leaf_blocks.begin(), small_leaf_blocks.end()) - small_leaf_blocks.begin());
  OctomapExpansion e;
  e.voxels = total;
  e.occupied_voxels = occupied;
  e.free_voxels = total - occupied;
  e.blocks = blocks;
  return e;
}

/// Every leaf of the tree as its voxels in `map`.
void expandLeaves(const octomap::OcTree& tree, LogOddsMap& map) {
  const unsigned max_depth = tree.getTreeDepth();
  for (auto it = tree.begin_leafs(), end = tree.end_leafs(); it != end; ++it) {
    const octomap::OcTreeKey base = it.getIndexKey();
    const std::int64_t edge = std::int64_t{1} << (max_depth - it.getDepth());
    const float l = it->getLogOdds();
    for (std::int64_t z = 0; z < edge; ++z) {
      for (std::int64_t y = 0; y < edge; ++y) {
        for (std::int64_t x = 0; x < edge; ++x) {
          map.setLogOdds(
              {base[0] + x - kOctoMaxVal, base[1] + y - kOctoMaxVal, base[2] + z - kOctoMaxVal}, l);
        }
      }
    }
  }
}

/// Reads and checks the file, counts what its leaves expand to, checks that and `use` against
/// the budget; expands the leaves into the returned map only when `expand`.
LogOddsMap readTree(const std::string& path, const LogOddsParams& params, const OctomapUse& use,
                    std::size_t max_voxels, OctomapExpansion* expansion, bool expand) {
  // a regular file only (a FIFO blocks, /dev/zero never ends), read up to its size, in budget
  const std::string bytes = readRegularFile(path, std::numeric_limits<std::uint64_t>::max());
  const OctomapFileInfo info = checkOctomapBytes(bytes, path);
  LogOddsParams p = params;
  p.resolution = info.resolution;
  LogOddsMap map(p);
  if (info.size == 0) return map;
  const std::unique_ptr<octomap::OcTree> tree = parseTree(bytes, info, p, path);
  // the map's blocks (and their hash slots) and what the caller builds from the voxels, against
  // the memory budget, before the expansion
  OctomapExpansion e = countExpansion(*tree, map, max_voxels, path);
  e.map_bytes = saturatingProduct(e.blocks, 2 * sizeof(detail::VoxelBlock) + 16);
  e.use_bytes = saturatingSum(saturatingProduct(e.occupied_voxels, use.bytes_per_occupied_voxel),
                              saturatingProduct(e.free_voxels, use.bytes_per_free_voxel));
  if (expansion != nullptr) *expansion = e;
  std::string what = path + " (" + std::to_string(e.voxels) + " voxels, " +
                     std::to_string(e.occupied_voxels) + " occupied, in " +
                     std::to_string(e.blocks) + " blocks";
  if (!use.purpose.empty()) what += ", " + use.purpose;
  checkMemory(saturatingSum(e.map_bytes, e.use_bytes), 1, what + ")");
  if (expand) expandLeaves(*tree, map);
  return map;
}

}  // namespace

LogOddsMap readOctomap(const std::string& path, const LogOddsParams& params,
                       std::size_t max_voxels) {
  return readTree(path, params, OctomapUse(), max_voxels, nullptr, true);
}

LogOddsMap readOctomap(const std::string& path, const LogOddsParams& params, const OctomapUse& use,
                       std::size_t max_voxels, OctomapExpansion* expansion) {
  return readTree(path, params, use, max_voxels, expansion, true);
}

OctomapExpansion inspectOctomap(const std::string& path, const LogOddsParams& params,
                                const OctomapUse& use, std::size_t max_voxels) {
  OctomapExpansion e;
  readTree(path, params, use, max_voxels, &e, false);
  return e;
}

}  // namespace metricmap
