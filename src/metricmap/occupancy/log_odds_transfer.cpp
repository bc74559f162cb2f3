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
constexpr std::size_t kVoxelBytes = 8 + 4;

void putHeader(ByteWriter& w, const LogOddsParams& p, std::uint64_t voxels) {
  w.put(kMagic);
  w.put(kVersion);
  for (double v : {p.resolution, p.prob_hit, p.prob_miss, p.clamp_min, p.clamp_max,
                   p.occupancy_threshold, p.max_range})
    w.put(v);
  w.put(voxels);
}

}  // namespace

std::vector<std::uint8_t> serializeLogOdds(const LogOddsMap& map) {
  return serializeLogOddsByOwner(map, 1)[0];
}

std::vector<std::vector<std::uint8_t>> serializeLogOddsByOwner(const LogOddsMap& map,
                                                               unsigned parts) {
  if (parts == 0) throw std::invalid_argument("serializeLogOddsByOwner: zero parts");
  std::vector<std::vector<std::uint8_t>> out(parts);
  std::vector<std::uint64_t> counts(parts, 0);
  for (unsigned p = 0; p < parts; ++p) {
    out[p].reserve(80 + (map.knownVoxels() / parts + map.knownVoxels() / 8 + 16) * kVoxelBytes);
    ByteWriter w(out[p]);
    putHeader(w, map.params(), 0);  // count patched below
  }
  map.forEachKnown([&](const VoxelKey& k, float l) {
    const unsigned owner = tileOwner(k.x, k.y, k.z, parts);
    std::uint8_t record[kVoxelBytes];
    const std::uint64_t packed = packVoxelKey(k.x, k.y, k.z);
    std::memcpy(record, &packed, 8);
    std::memcpy(record + 8, &l, 4);
    out[owner].insert(out[owner].end(), record, record + kVoxelBytes);
    ++counts[owner];
  });
  for (unsigned p = 0; p < parts; ++p)
    std::memcpy(out[p].data() + 64, &counts[p], 8);  // after magic, version, 7 params
  return out;
}

namespace {

/// Checks a buffer's header and records; returns its parameters and voxel count.
std::uint64_t checkBuffer(ByteReader& r, LogOddsParams& p) {
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
  if (n > r.remaining() / kVoxelBytes || r.remaining() != n * kVoxelBytes)
    r.fail("holds " + std::to_string(r.remaining()) + " bytes of voxels, not " + std::to_string(n) +
           " voxels of " + std::to_string(kVoxelBytes) + " bytes");
  return n;
}

void checkRecord(ByteReader& r, std::uint64_t packed, float l) {
  if (packed >> 63) r.fail("a voxel key outside the key space");
  if (!std::isfinite(l)) r.fail("a non-finite log-odds");
}

}  // namespace

void mergeSerializedLogOdds(LogOddsMap& map, const std::uint8_t* data, std::size_t size,
                            const std::string& what) {
  ByteReader check(data, size, what);
  LogOddsParams p;
  const std::uint64_t n = checkBuffer(check, p);
  const LogOddsParams& q = map.params();
  if (p.resolution != q.resolution || p.prob_hit != q.prob_hit || p.prob_miss != q.prob_miss ||
      p.clamp_min != q.clamp_min || p.clamp_max != q.clamp_max ||
      p.occupancy_threshold != q.occupancy_threshold)
    check.fail("resolution or sensor model differs from this map's");
  const std::size_t start = size - check.remaining();
  for (std::uint64_t i = 0; i < n; ++i) {
    const std::uint64_t packed = check.get<std::uint64_t>();
    checkRecord(check, packed, check.get<float>());
  }
  ByteReader r(data + start, size - start, what);
  for (std::uint64_t i = 0; i < n; ++i) {
    const std::uint64_t packed = r.get<std::uint64_t>();
    map.mergeLogOdds(unpackVoxelKey(packed), r.get<float>());
  }
}

LogOddsMap deserializeLogOdds(const std::uint8_t* data, std::size_t size, const std::string& what) {
  ByteReader r(data, size, what);
  LogOddsParams p;
  const std::uint64_t n = checkBuffer(r, p);
  LogOddsMap map(p);
  for (std::uint64_t i = 0; i < n; ++i) {
    const std::uint64_t packed = r.get<std::uint64_t>();
    const float l = r.get<float>();
    checkRecord(r, packed, l);
    map.setLogOdds(unpackVoxelKey(packed), l);
  }
  if (map.knownVoxels() != n) r.fail("a voxel appears twice");
  return map;
}

}  // namespace metricmap
