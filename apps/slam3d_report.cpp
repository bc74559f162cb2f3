#include "slam3d_report.h"

#include <cstdio>
#include <map>

#include <nlohmann/json.hpp>

#include "cli_common.h"
#include "metricmap/slam3d/slam3d_run.h"

namespace metricmap::cli {

void emitSlam3DReport(const std::string& input, const Slam3DRun& run, const Slam3DTimes& times,
                      const std::string& format, OutputSet& outputs) {
  const Slam3D& slam = *run.slam;
  const Slam3DTiming& t = slam.timing();
  std::map<std::string, std::size_t> reasons;
  std::size_t descriptor = 0, radius = 0;
  for (const Slam3DLoop& l : slam.loopChecks()) {
    (l.method == "descriptor" ? descriptor : radius) += 1;
    if (!l.check.accepted) ++reasons[l.check.reason];
  }
  const std::size_t rejected = slam.loopChecks().size() - slam.verifiedLoops();
  const double rtf = times.total > 0 ? times.span / times.total : 0.0;
  const nlohmann::json j = {
      {"input", input},
      {"keyframes", slam.size()},
      {"loop_candidates",
       {{"total", slam.loopChecks().size()}, {"descriptor", descriptor}, {"radius", radius}}},
      {"loops", {{"verified", slam.verifiedLoops()}, {"rejected", rejected}, {"reasons", reasons}}},
      {"optimizations", t.optimizations},
      {"final_chi2", slam.graph().chi2()},
      {"seconds",
       {{"read", run.read_seconds},
        {"odometry", run.odometry_seconds},
        {"descriptors", t.descriptors},
        {"loop_search", t.search},
        {"loop_verify", t.verify},
        {"optimize", t.optimize},
        {"maps", times.maps},
        {"write", times.write},
        {"total", times.total}}},
      {"scan_seconds", times.span},
      {"real_time_factor", rtf},
      {"peak_memory_mib", times.peak_mib},
      {"slam_memory_mib", double(slam.bytes()) / 1048576.0}};
  if (format == "json") return emit(j.dump(2) + "\n", outputs);
  char text[1024];
  std::snprintf(text, sizeof text,
                "%s: %zu keyframes\n"
                "loops: %zu candidates (%zu descriptor, %zu radius), %zu verified, %zu rejected; "
                "%zu optimisations, final chi2 %.6g\n"
                "time: %.2f s (read %.2f, odometry %.2f, descriptors %.2f, search %.2f, verify "
                "%.2f, optimise %.2f, maps %.2f, write %.2f) for %.6g s of scans: %.3gx real "
                "time; peak memory %.0f MiB\n",
                input.c_str(), slam.size(), slam.loopChecks().size(), descriptor, radius,
                slam.verifiedLoops(), rejected, t.optimizations, slam.graph().chi2(), times.total,
                run.read_seconds, run.odometry_seconds, t.descriptors, t.search, t.verify,
                t.optimize, times.maps, times.write, times.span, rtf, times.peak_mib);
  emit(text, outputs);
}

}  // namespace metricmap::cli
