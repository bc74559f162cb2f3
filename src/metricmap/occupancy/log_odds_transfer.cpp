#include "metricmap/occupancy/log_odds_transfer.h"

#include <cmath>
#include <cstring>
#include <stdexcept>

#include "metricmap/common/byte_buffer.h"
#include "metricmap/common/tile_owner.h"
#include "metricmap/exceptions.h"

namespace metricmap {
namespace {

constexpr std::uint32_t kMagic = 0x4F4C'4D4Du;  // "MMLO" read as little-endian bytes
constexpr std::uint32_t kVersion = 1;
constexpr std::size_t kBlockHeadBytes = 8 + 8 * detail::kBlockWords;  // key, known bits
constexpr std::size_t kHeaderBytes = 4 + 4 + 7 * 8 + 8;  // magic, version, parameters, blocks

void putHeader(ByteWriter& w, const LogOddsParams& p, std::uint64_t voxels) {
  w.put(kMagic);
  w.put(kVersion);
  for (double v : {p.resolution, p.prob_hit, p.prob_miss, p.clamp_min, p.clamp_max,
                   p.occupancy_threshold, p.max_range})
    w.put(v);
  w.put(voxels);
}

/// The part of `parts` that owns a block (tiles are whole blocks).
unsigned blockOwner(std::uint64_t key, unsigned parts) {
  const VoxelKey b = unpackVoxelKey(key);  // block coordinates: its tile is its voxels' tile
  return tileOwner(b.x * detail::kBlockEdge, b.y * detail::kBlockEdge, b.z * detail::kBlockEdge,
                   parts);
}

}  // namespace

std::vector<std::uint8_t> serializeLogOdds(const LogOddsMap& map) {
  return serializeLogOddsByOwner(map, 1)[0];
}

std::vector<std::vector<std::uint8_t>> serializeLogOddsByOwner(const LogOddsMap& map,
                                                               unsigned parts, unsigned keep) {
  if (parts == 0) throw std::invalid_argument("serializeLogOddsByOwner: zero parts");
  std::vector<std::vector<std::uint8_t>> out(parts);
  std::vector<std::uint64_t> counts(parts, 0);
  for (unsigned p = 0; p < parts; ++p) {
    ByteWriter w(out[p]);
    putHeader(w, map.params(), 0);  // block count patched below
  }
  map.forEachBlock([&](std::uint64_t key, const std::uint64_t* known, const float* values) {
    const unsigned owner = blockOwner(key, parts);
    if (owner == keep) return;
    std::vector<std::uint8_t>& o = out[owner];
    const std::size_t at = o.size();
    int n = 0;
    for (int w = 0; w < detail::kBlockWords; ++w) n += __builtin_popcountll(known[w]);
    o.resize(at + kBlockHeadBytes + 4 * static_cast<std::size_t>(n));
    std::uint8_t* dst = o.data() + at;
    std::memcpy(dst, &key, 8);
    std::memcpy(dst + 8, known, 8 * detail::kBlockWords);
    dst += kBlockHeadBytes;
    for (int w = 0; w < detail::kBlockWords; ++w) {
      for (std::uint64_t bits = known[w]; bits != 0; bits &= bits - 1) {
        std::memcpy(dst, &values[w * 64 + __builtin_ctzll(bits)], 4);
        dst += 4;
      }
    }
    ++counts[owner];
  });
  for (unsigned p = 0; p < parts; ++p) std::memcpy(out[p].data() + kHeaderBytes - 8, &counts[p], 8);
  return out;
}

void mergeOwnedBlocks(LogOddsMap& into, const LogOddsMap& from, unsigned part, unsigned parts) {
  if (&into == &from)
    throw std::invalid_argument("mergeOwnedBlocks: cannot merge a map into itself");
  float packed[detail::kBlockWords * 64];
  from.forEachBlock([&](std::uint64_t key, const std::uint64_t* known, const float* values) {
    if (blockOwner(key, parts) != part) return;
    float* dst = packed;
    for (int w = 0; w < detail::kBlockWords; ++w) {
      for (std::uint64_t bits = known[w]; bits != 0; bits &= bits - 1)
        *dst++ = values[w * 64 + __builtin_ctzll(bits)];
    }
    into.mergeBlock(key, known, packed);
  });
}

namespace {

/// Checks a buffer's header; returns its parameters and block count.
std::uint64_t checkHeader(ByteReader& r, LogOddsParams& p) {
  if (r.get<std::uint32_t>() != kMagic) r.fail("not a log-odds buffer (bad magic)");
  const std::uint32_t version = r.get<std::uint32_t>();
  if (version != kVersion)
    r.fail("log-odds buffer version " + std::to_string(version) + ", expected " +
           std::to_string(kVersion));
  for (double* v : {&p.resolution, &p.prob_hit, &p.prob_miss, &p.clamp_min, &p.clamp_max,
                    &p.occupancy_threshold, &p.max_range})
    *v = r.get<double>();
  try {
    validateLogOddsParams(p);
  } catch (const std::invalid_argument& e) {
    r.fail(std::string("bad parameters: ") + e.what());
  }
  const std::uint64_t n = r.get<std::uint64_t>();
  if (n > r.remaining() / kBlockHeadBytes) r.fail("truncated: fewer blocks than announced");
  return n;
}

/// One block record, checked: key, known bits, values (pointer into the buffer).
struct BlockRecord {
  std::uint64_t key;
  std::uint64_t known[detail::kBlockWords];
  std::vector<float> values;
};

void readBlock(ByteReader& r, BlockRecord& b) {
  b.key = r.get<std::uint64_t>();
  constexpr std::int64_t lim = kVoxelKeyLimit >> detail::kBlockShift;
  const VoxelKey k = unpackVoxelKey(b.key);
  if ((b.key >> 63) || k.x < -lim || k.x >= lim || k.y < -lim || k.y >= lim || k.z < -lim ||
      k.z >= lim)
    r.fail("a voxel block outside the key space");
  int n = 0;
  for (std::uint64_t& w : b.known) {
    w = r.get<std::uint64_t>();
    n += __builtin_popcountll(w);
  }
  if (n == 0) r.fail("a block without known voxels");
  if (r.remaining() < 4 * static_cast<std::size_t>(n)) r.fail("truncated");
  b.values.resize(static_cast<std::size_t>(n));
  for (float& v : b.values) {
    v = r.get<float>();
    if (!std::isfinite(v)) r.fail("a non-finite log-odds");
  }
}

}  // namespace

void mergeSerializedLogOdds(LogOddsMap& map, const std::uint8_t* data, std::size_t size,
                            const std::string& what) {
  ByteReader check(data, size, what);
  LogOddsParams p;
  const std::uint64_t n = checkHeader(check, p);
  const LogOddsParams& q = map.params();
  if (p.resolution != q.resolution || p.prob_hit != q.prob_hit || p.prob_miss != q.prob_miss ||
      p.clamp_min != q.clamp_min || p.clamp_max != q.clamp_max ||
      p.occupancy_threshold != q.occupancy_threshold)
    check.fail("resolution or sensor model differs from this map's");
  const std::size_t start = size - check.remaining();
  BlockRecord b;
  for (std::uint64_t i = 0; i < n; ++i) readBlock(check, b);  // all checked first
  if (check.remaining() != 0) check.fail("trailing bytes after the last block");
  ByteReader r(data + start, size - start, what);
  for (std::uint64_t i = 0; i < n; ++i) {
    readBlock(r, b);
    map.mergeBlock(b.key, b.known, b.values.data());
  }
}

LogOddsMap deserializeLogOdds(const std::uint8_t* data, std::size_t size, const std::string& what) {
  ByteReader r(data, size, what);
  LogOddsParams p;
  const std::uint64_t n = checkHeader(r, p);
  LogOddsMap map(p);
  BlockRecord b;
  std::size_t voxels = 0;
  for (std::uint64_t i = 0; i < n; ++i) {
    readBlock(r, b);
    voxels += b.values.size();
    map.mergeBlock(b.key, b.known, b.values.data());
  }
  if (r.remaining() != 0) r.fail("trailing bytes after the last block");
  if (map.knownVoxels() != voxels) r.fail("a voxel appears twice");
  return map;
}

}  // namespace metricmap
