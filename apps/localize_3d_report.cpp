#include <cmath>
#include <cstdio>

#include <nlohmann/json.hpp>

#include "cli_common.h"
#include "localize_report.h"

namespace metricmap::cli {

void emitLocalizeReport(const std::string& input, const std::string& map,
                        const std::vector<std::size_t>& frames, const Localize3DRun& run,
                        const LocalizeTimes& times, const std::string& format, OutputSet& outputs) {
  const Localizer3DStats& s = run.localizer->stats();
  const double total = times.total, span = times.log;
  const std::size_t recoveries = s.fixes > 0 ? s.fixes - 1 : 0;
  nlohmann::json first = nullptr;
  double first_seconds = std::nan("");
  if (s.first_fix) {
    const std::size_t k = *s.first_fix;
    first = {{"scan", k}, {"frame", frames[k]}};
    if (std::isfinite(run.stamps[k]) && std::isfinite(run.stamps.front())) {
      first_seconds = run.stamps[k] - run.stamps.front();
      first["seconds"] = first_seconds;
    }
  }
  const double rtf = total > 0 ? span / total : 0.0;
  const double track_ms = s.scans > s.global_searches
                              ? 1e3 * s.track_seconds / double(s.scans - s.global_searches)
                              : 0.0;
  if (format == "json") {
    nlohmann::json status = nlohmann::json::array(), score = nlohmann::json::array(),
                   margin = nlohmann::json::array();
    for (const Localization3D& r : run.results) {
      status.push_back(statusName(r.status));
      score.push_back(std::round(r.score * 1e4) / 1e4);
      margin.push_back(std::round(r.margin * 1e4) / 1e4);
    }
    const nlohmann::json j = {
        {"input", input},
        {"map", map},
        {"dimension", 3},
        {"scans", s.scans},
        {"localised", s.localised},
        {"first_fix", first},
        {"global_searches", s.global_searches},
        {"ambiguous", s.ambiguous},
        {"losses", s.losses},
        {"recoveries", recoveries},
        {"places", s.places},
        {"candidates", s.candidates},
        {"seconds",
         {{"map", times.map},
          {"setup", s.setup_seconds},
          {"read", run.read_seconds},
          {"global", s.global_seconds},
          {"track", s.track_seconds},
          {"write", times.write},
          {"total", total}}},
        {"track_ms_per_scan", track_ms},
        {"log_seconds", span},
        {"real_time_factor", rtf},
        {"per_scan",
         {{"frame", frames}, {"status", status}, {"score", score}, {"margin", margin}}}};
    return emit(j.dump(2) + "\n", outputs);
  }
  char text[1024];
  std::snprintf(text, sizeof text,
                "%s in %s: %zu of %zu scans localised; first fix at scan %s%s; %zu global "
                "searches over %zu places (%zu ambiguous), %zu losses, %zu recoveries\n"
                "time: %.2f s (map %.2f, setup %.2f, read %.2f, global %.2f, track %.2f = %.1f "
                "ms per tracked scan, write %.2f) for %.6g s of log: %.3gx real time\n",
                input.c_str(), map.c_str(), s.localised, s.scans,
                s.first_fix ? std::to_string(frames[*s.first_fix]).c_str() : "none",
                std::isfinite(first_seconds)
                    ? (" (" + plainNumber(first_seconds) + " s into the log)").c_str()
                    : "",
                s.global_searches, s.places, s.ambiguous, s.losses, recoveries, total, times.map,
                s.setup_seconds, run.read_seconds, s.global_seconds, s.track_seconds, track_ms,
                times.write, span, rtf);
  emit(text, outputs);
}

}  // namespace metricmap::cli
