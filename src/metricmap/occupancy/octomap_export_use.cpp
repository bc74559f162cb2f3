#include "metricmap/occupancy/octomap_export_use.h"

#include <cstdint>

namespace metricmap {

OctomapUse octomapExportUse(const std::vector<std::string>& tree_outputs,
                            const std::vector<std::string>& cloud_outputs) {
  // OctoMap tree before pruning: a 16-byte leaf node (+ allocator overhead), its share of the
  // parents' nodes and child arrays
  constexpr std::uint64_t kOctomapNodeBytes = 48;
  // a cloud point (16 bytes), the voxel centre (24) and the PCD writer's copy
  constexpr std::uint64_t kCloudPointBytes = 64;
  OctomapUse use;
  std::string purpose;
  for (const std::string& name : tree_outputs) {
    use.bytes_per_occupied_voxel = use.bytes_per_free_voxel = kOctomapNodeBytes;
    purpose += (purpose.empty() ? "" : " and ") + name;
  }
  for (const std::string& name : cloud_outputs) {
    use.bytes_per_occupied_voxel += kCloudPointBytes;
    purpose += (purpose.empty() ? "" : " and ") + name;
  }
  if (!purpose.empty()) use.purpose = "exported as " + purpose;
  return use;
}

}  // namespace metricmap
