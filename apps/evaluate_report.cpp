#include "evaluate_report.h"

#include <algorithm>
#include <cstdio>
#include <utility>

#include <nlohmann/json.hpp>

#include "metricmap/evaluation/rotation_angle.h"
#include "table.h"

namespace metricmap::cli {
namespace {

nlohmann::json infoJson(const LoadedTrajectory& l) {
  return {
      {"path", l.path}, {"poses", l.trajectory.size()}, {"format", trajectoryFormatName(l.format)}};
}

std::string infoLine(const LoadedTrajectory& l) {
  return l.path + " (" + std::to_string(l.trajectory.size()) + " poses, " +
         trajectoryFormatName(l.format) + " form)";
}

nlohmann::json statsJson(const ErrorStatistics& s) {
  return {{"count", s.count}, {"rmse", s.rmse}, {"mean", s.mean}, {"median", s.median},
          {"std", s.stddev},  {"min", s.min},   {"max", s.max}};
}

/// Positions in `e`'s used relations, largest `values` first (ties: input order), at most `n`.
std::vector<std::size_t> worstFirst(const std::vector<double>& values, std::size_t n) {
  std::vector<std::size_t> order(values.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return values[a] > values[b]; });
  order.resize(std::min(n, order.size()));
  return order;
}

/// A time stamp to the microsecond (log stamps are seconds since 1970).
std::string stamp(double t) {
  char s[40];
  std::snprintf(s, sizeof s, "%.6f", t);
  return s;
}

void addStatsRow(Table& t, const std::string& name, const ErrorStatistics& s) {
  t.addRow({name, std::to_string(s.count), num(s.rmse), num(s.mean), num(s.median), num(s.stddev),
            num(s.min), num(s.max)});
}

}  // namespace

std::string num(double v) {
  char s[32];
  std::snprintf(s, sizeof s, "%.6g", v);
  return s;
}

std::string referenceReport(const LoadedTrajectory& est, const LoadedTrajectory& ref,
                            const TrajectoryEvaluation& ev, const EvaluationConfig& config,
                            bool per_frame, const std::string& format) {
  const bool by_stamps = ev.pairs.mode == PairingMode::Stamps;
  const std::string pairing =
      by_stamps ? "by time stamps (nearest within " + num(config.max_time_diff) + " s)"
                : "by index";
  const Alignment& a = ev.alignment;
  const KittiDrift& d = ev.drift;
  auto nullable = [&](std::size_t n, double v) { return n ? nlohmann::json(v) : nullptr; };
  if (format == "json") {
    nlohmann::json lengths = nlohmann::json::array();
    for (const KittiDriftLength& l : d.lengths) {
      lengths.push_back({{"length_m", l.length},
                         {"segments", l.segments},
                         {"translation_percent", nullable(l.segments, l.translation_percent)},
                         {"rotation_deg_per_m", nullable(l.segments, l.rotation_deg_per_m)}});
    }
    nlohmann::json rot = nlohmann::json::array();
    for (int r = 0; r < 3; ++r)
      rot.push_back({a.rotation(r, 0), a.rotation(r, 1), a.rotation(r, 2)});
    return nlohmann::json(
               {{"estimate", infoJson(est)},
                {"reference", infoJson(ref)},
                {"pairing",
                 {{"mode", by_stamps ? "stamps" : "index"},
                  {"pairs", ev.pairs.size()},
                  {"max_time_diff_s", by_stamps ? nlohmann::json(config.max_time_diff) : nullptr}}},
                {"alignment",
                 {{"mode", alignmentModeName(ev.alignment_mode)},
                  {"scale", a.scale},
                  {"rotation", rot},
                  {"rotation_deg", rotationAngleDeg(a.rotation)},
                  {"translation_m", {a.translation.x(), a.translation.y(), a.translation.z()}}}},
                {"ate",
                 {{"translation_m", statsJson(ev.ate.translation_stats)},
                  {"rotation_deg", statsJson(ev.ate.rotation_stats)}}},
                {"rpe",
                 {{"delta_frames", 1},
                  {"translation_m", statsJson(ev.rpe.translation_stats)},
                  {"rotation_deg", statsJson(ev.rpe.rotation_stats)},
                  {"per_frame",
                   {{"translation_m", ev.rpe.translation},
                    {"rotation_deg", ev.rpe.rotation_deg}}}}},
                {"failed_steps",
                 {{"max_translation_m", ev.steps.limits.max_translation},
                  {"max_rotation_deg", ev.steps.limits.max_rotation_deg},
                  {"steps", ev.steps.steps},
                  {"count", ev.steps.failed.size()},
                  {"failed_from_pose", ev.steps.failed}}},
                {"kitti_drift",
                 {{"path_length_m", d.path_length},
                  {"step_frames", config.drift.step},
                  {"segments", d.segments},
                  {"translation_percent", nullable(d.segments, d.translation_percent)},
                  {"rotation_deg_per_m", nullable(d.segments, d.rotation_deg_per_m)},
                  {"lengths", lengths}}}})
               .dump(2) +
           "\n";
  }
  std::string out = "estimate:  " + infoLine(est) + "\nreference: " + infoLine(ref) +
                    "\npairing:   " + pairing + ", " + std::to_string(ev.pairs.size()) +
                    " pairs\nalignment: " + alignmentModeName(ev.alignment_mode) +
                    " (Umeyama on positions): scale " + num(a.scale) + ", rotation " +
                    num(rotationAngleDeg(a.rotation)) + " deg, translation " +
                    num(a.translation.x()) + " " + num(a.translation.y()) + " " +
                    num(a.translation.z()) + " m\n\n";
  Table stats({"metric", "count", "rmse", "mean", "median", "std", "min", "max"});
  addStatsRow(stats, "ate_translation_m", ev.ate.translation_stats);
  addStatsRow(stats, "ate_rotation_deg", ev.ate.rotation_stats);
  addStatsRow(stats, "rpe_translation_m", ev.rpe.translation_stats);
  addStatsRow(stats, "rpe_rotation_deg", ev.rpe.rotation_stats);
  out += stats.render(TableStyle::Aligned) + "failed steps (RPE > " +
         num(ev.steps.limits.max_translation) + " m or > " + num(ev.steps.limits.max_rotation_deg) +
         " deg): " + std::to_string(ev.steps.failed.size()) + " of " +
         std::to_string(ev.steps.steps) + "\nKITTI drift (devkit: 100-800 m segments every 10 " +
         "frames, estimate as given), reference path " + num(d.path_length) + " m: ";
  if (d.segments == 0) {
    out += "no segment fits (the path is shorter than the shortest segment)\n";
  } else {
    out += std::to_string(d.segments) + " segments\n";
    Table drift({"length_m", "segments", "translation_%", "rotation_deg_per_m"});
    for (const KittiDriftLength& l : d.lengths) {
      drift.addRow({num(l.length), std::to_string(l.segments),
                    l.segments ? num(l.translation_percent) : "-",
                    l.segments ? num(l.rotation_deg_per_m) : "-"});
    }
    drift.addRow(
        {"all", std::to_string(d.segments), num(d.translation_percent), num(d.rotation_deg_per_m)});
    out += drift.render(TableStyle::Aligned);
  }
  if (per_frame) {
    Table frames({"frame", "rpe_translation_m", "rpe_rotation_deg"});
    for (std::size_t i = 0; i < ev.rpe.translation.size(); ++i)
      frames.addRow({std::to_string(i), num(ev.rpe.translation[i]), num(ev.rpe.rotation_deg[i])});
    out += "\n" + frames.render(TableStyle::Aligned);
  }
  return out;
}

std::string relationsReport(const LoadedTrajectory& est, const RelationsInput& in,
                            const RelationError& e, const std::string& format) {
  const std::vector<PoseRelation>& relations = *in.relations;
  const std::pair<const char*, const MeanAndStd*> rows[] = {
      {"abs_translation_m", &e.translation_abs},
      {"sqr_translation_m2", &e.translation_sq},
      {"abs_rotation_deg", &e.rotation_abs_deg},
      {"sqr_rotation_deg2", &e.rotation_sq_deg}};
  if (format == "json") {
    nlohmann::json j = {{"estimate", infoJson(est)},
                        {"relations",
                         {{"path", in.path},
                          {"count", relations.size()},
                          {"used", e.used},
                          {"skipped", e.skipped.size()},
                          {"stamps_placed_by_odometry", e.interpolated},
                          {"max_time_diff_s", in.max_time_diff}}}};
    nlohmann::json skipped = nlohmann::json::array();
    for (std::size_t k : e.skipped)
      skipped.push_back(
          {{"index", k}, {"stamp1", relations[k].stamp1}, {"stamp2", relations[k].stamp2}});
    j["relations"]["skipped_relations"] = skipped;
    for (const auto& [name, v] : rows) j[name] = {{"mean", v->mean}, {"std", v->stddev}};
    const auto entry = [&](std::size_t u) {
      const std::size_t k = e.used_relations[u];
      return nlohmann::json{{"index", k},
                            {"stamp1", relations[k].stamp1},
                            {"stamp2", relations[k].stamp2},
                            {"translation_m", e.translation[u]},
                            {"rotation_deg", e.rotation_deg[u]}};
    };
    nlohmann::json per = nlohmann::json::array();
    for (std::size_t u = 0; u < e.used; ++u) per.push_back(entry(u));
    j["per_relation"] = per;
    nlohmann::json by_t = nlohmann::json::array(), by_r = nlohmann::json::array();
    for (std::size_t u : worstFirst(e.translation, kWorstRelations)) by_t.push_back(entry(u));
    for (std::size_t u : worstFirst(e.rotation_deg, kWorstRelations)) by_r.push_back(entry(u));
    j["worst"] = {{"by_translation", by_t}, {"by_rotation", by_r}};
    return j.dump(2) + "\n";
  }
  std::string out =
      "estimate:  " + infoLine(est) + "\nrelations: " + in.path + " (" +
      std::to_string(relations.size()) + " relations: " + std::to_string(e.used) + " used, " +
      std::to_string(e.skipped.size()) + " skipped, their stamps not within " +
      num(in.max_time_diff) + " s of the estimate's" +
      (in.odometry.empty() ? ""
                           : " nor placed by the odometry; " + std::to_string(e.interpolated) +
                                 " stamps placed by the odometry") +
      ")\n\n";
  Table t({"metric", "mean", "std"});
  for (const auto& [name, v] : rows) t.addRow({name, num(v->mean), num(v->stddev)});
  out += t.render(TableStyle::Aligned);
  Table worst({"relation", "stamp1", "stamp2", "translation_m", "rotation_deg"});
  for (std::size_t u : worstFirst(e.translation, kWorstRelations)) {
    const std::size_t k = e.used_relations[u];
    worst.addRow({std::to_string(k), stamp(relations[k].stamp1), stamp(relations[k].stamp2),
                  num(e.translation[u]), num(e.rotation_deg[u])});
  }
  return out + "\nworst relations by translational error (--format json: every relation):\n" +
         worst.render(TableStyle::Aligned);
}

}  // namespace metricmap::cli
