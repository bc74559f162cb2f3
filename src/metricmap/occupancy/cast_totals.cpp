#include "metricmap/occupancy/cast_totals.h"

namespace metricmap {

ScanCastTotals reduceCastTotals(const ScanCastTotals& local, const CastTotalsCollectives& c,
                                double& insert_cpu_s) {
  std::vector<std::uint64_t> counts = {
      local.frames, local.points,     local.beams,
      local.cut,    local.non_finite, static_cast<std::uint64_t>(local.insert_s * 1e9)};
  std::vector<double> seconds = {local.load_s, local.insert_s};
  c.sum(counts);
  c.max(seconds);
  ScanCastTotals tot;
  tot.frames = counts[0];
  tot.points = counts[1];
  tot.beams = counts[2];
  tot.cut = counts[3];
  tot.non_finite = counts[4];
  insert_cpu_s = static_cast<double>(counts[5]) * 1e-9;
  tot.load_s = seconds[0];
  tot.insert_s = seconds[1];
  return tot;
}

}  // namespace metricmap
