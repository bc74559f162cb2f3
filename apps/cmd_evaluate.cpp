// metricmap evaluate EST (--reference REF | --relations FILE): ATE, per-frame RPE and KITTI drift
// of an estimated trajectory against a reference one, or the relation metric of Kümmerle et al.
#include <cstdio>
#include <memory>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "cli_common.h"
#include "commands.h"
#include "metricmap/datasets/scan_source.h"
#include "metricmap/datasets/source_odometry.h"
#include "metricmap/evaluation/relation_error.h"
#include "metricmap/evaluation/rotation_angle.h"
#include "metricmap/evaluation/trajectory_evaluation.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/trajectory.h"
#include "metricmap/io/trajectory_relations.h"
#include "table.h"

namespace metricmap::cli {
namespace {

struct EvaluateOptions {
  std::string estimate, reference, relations, odometry, align = "rigid", format = "table";
  std::string est_format = "auto", ref_format = "auto";
  double max_time_diff = 0.01;
  bool per_frame = false;
};

std::string num(double v) {
  char s[32];
  std::snprintf(s, sizeof s, "%.6g", v);
  return s;
}

struct Loaded {
  Trajectory trajectory;
  TrajectoryFormat format = TrajectoryFormat::Auto;
  nlohmann::json info;
  std::string line;
};

Loaded load(const std::string& path, const std::string& format) {
  Loaded l;
  l.trajectory = readTrajectoryFile(path, parseTrajectoryFormat(format), &l.format);
  const std::string form = trajectoryFormatName(l.format);
  l.info = {{"path", path}, {"poses", l.trajectory.size()}, {"format", form}};
  l.line = path + " (" + std::to_string(l.trajectory.size()) + " poses, " + form + " form)";
  return l;
}

nlohmann::json statsJson(const ErrorStatistics& s) {
  return {{"count", s.count}, {"rmse", s.rmse}, {"mean", s.mean}, {"median", s.median},
          {"std", s.stddev},  {"min", s.min},   {"max", s.max}};
}

void addStatsRow(Table& t, const std::string& name, const ErrorStatistics& s) {
  t.addRow({name, std::to_string(s.count), num(s.rmse), num(s.mean), num(s.median), num(s.stddev),
            num(s.min), num(s.max)});
}

std::string runReference(const EvaluateOptions& o, const CLI::App& app) {
  const Loaded est = load(o.estimate, o.est_format), ref = load(o.reference, o.ref_format);
  EvaluationConfig config;
  config.alignment = parseAlignmentMode(o.align);
  config.max_time_diff = o.max_time_diff;
  TrajectoryEvaluation ev;
  try {
    ev = evaluateTrajectory(est.trajectory, ref.trajectory, config);
  } catch (const std::invalid_argument& e) {
    throw InputError(o.estimate + " against " + o.reference + ": " + e.what());
  }
  const bool by_stamps = ev.pairs.mode == PairingMode::Stamps;
  refuseIgnored(app, "--max-time-diff", by_stamps,
                "here: the poses pair by index (a trajectory without time stamps)");
  const std::string pairing =
      by_stamps ? "by time stamps (nearest within " + num(o.max_time_diff) + " s)" : "by index";
  const Alignment& a = ev.alignment;
  const KittiDrift& d = ev.drift;
  auto nullable = [&](std::size_t n, double v) { return n ? nlohmann::json(v) : nullptr; };
  if (o.format == "json") {
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
               {{"estimate", est.info},
                {"reference", ref.info},
                {"pairing",
                 {{"mode", by_stamps ? "stamps" : "index"},
                  {"pairs", ev.pairs.size()},
                  {"max_time_diff_s", by_stamps ? nlohmann::json(o.max_time_diff) : nullptr}}},
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
  std::string out = "estimate:  " + est.line + "\nreference: " + ref.line +
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
  out += stats.render(TableStyle::Aligned) + "\nKITTI drift (devkit: 100-800 m segments every 10 " +
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
  if (o.per_frame) {
    Table frames({"frame", "rpe_translation_m", "rpe_rotation_deg"});
    for (std::size_t i = 0; i < ev.rpe.translation.size(); ++i)
      frames.addRow({std::to_string(i), num(ev.rpe.translation[i]), num(ev.rpe.rotation_deg[i])});
    out += "\n" + frames.render(TableStyle::Aligned);
  }
  return out;
}

std::string runRelations(const EvaluateOptions& o) {
  const Loaded est = load(o.estimate, o.est_format);
  if (!est.trajectory.hasStamps()) {
    throw InputError(o.estimate +
                     ": no time stamps (KITTI form); the relation metric needs the "
                     "estimate in TUM form");
  }
  const std::vector<PoseRelation> relations = readRelations(o.relations);
  // The log's raw odometry places relation stamps the estimate lacks (a CARMEN log, or a
  // trajectory file with stamps).
  Trajectory odometry;
  if (!o.odometry.empty()) {
    if (scanSourceKind(o.odometry, "auto") == "carmen") {
      odometry = sourceOdometry(*openScanSource(o.odometry));
    } else {
      odometry = load(o.odometry, "auto").trajectory;
      if (!odometry.hasStamps())
        throw InputError(o.odometry +
                         ": no time stamps (KITTI form); --odometry needs a CARMEN "
                         "log or a TUM trajectory");
    }
  }
  const RelationError e = relationError(est.trajectory, relations, o.max_time_diff,
                                        o.odometry.empty() ? nullptr : &odometry);
  if (e.used == 0) {
    throw InputError(o.relations + ": none of its " + std::to_string(relations.size()) +
                     " relations has both stamps within " + num(o.max_time_diff) +
                     " s of a stamp of " + o.estimate +
                     (o.odometry.empty() ? "" : " or within the span of " + o.odometry));
  }
  const std::pair<const char*, const MeanAndStd*> rows[] = {
      {"abs_translation_m", &e.translation_abs},
      {"sqr_translation_m2", &e.translation_sq},
      {"abs_rotation_deg", &e.rotation_abs_deg},
      {"sqr_rotation_deg2", &e.rotation_sq_deg}};
  if (o.format == "json") {
    nlohmann::json j = {{"estimate", est.info},
                        {"relations",
                         {{"path", o.relations},
                          {"count", relations.size()},
                          {"used", e.used},
                          {"skipped", e.skipped.size()},
                          {"stamps_placed_by_odometry", e.interpolated},
                          {"max_time_diff_s", o.max_time_diff}}}};
    nlohmann::json skipped = nlohmann::json::array();
    for (std::size_t k : e.skipped)
      skipped.push_back(
          {{"index", k}, {"stamp1", relations[k].stamp1}, {"stamp2", relations[k].stamp2}});
    j["relations"]["skipped_relations"] = skipped;
    for (const auto& [name, v] : rows) j[name] = {{"mean", v->mean}, {"std", v->stddev}};
    return j.dump(2) + "\n";
  }
  std::string out =
      "estimate:  " + est.line + "\nrelations: " + o.relations + " (" +
      std::to_string(relations.size()) + " relations: " + std::to_string(e.used) + " used, " +
      std::to_string(e.skipped.size()) + " skipped, their stamps not within " +
      num(o.max_time_diff) + " s of the estimate's" +
      (o.odometry.empty() ? ""
                          : " nor placed by the odometry; " + std::to_string(e.interpolated) +
                                " stamps placed by the odometry") +
      ")\n\n";
  Table t({"metric", "mean", "std"});
  for (const auto& [name, v] : rows) t.addRow({name, num(v->mean), num(v->stddev)});
  return out + t.render(TableStyle::Aligned);
}

}  // namespace

void addEvaluateCommand(CLI::App& app) {
  auto o = std::make_shared<EvaluateOptions>();
  CLI::App* sub = app.add_subcommand(
      "evaluate", "Trajectory error: ATE, per-frame RPE, KITTI drift, or the relation metric");
  sub->add_option("estimate", o->estimate, "Estimated trajectory (KITTI or TUM form)")->required();
  auto* ref = sub->add_option("--reference", o->reference, "Reference trajectory (KITTI or TUM)");
  auto* rel = sub->add_option("--relations", o->relations,
                              "Relations file 't1 t2 x y z roll pitch yaw' (Kümmerle et al. 2009)")
                  ->excludes(ref);
  sub->add_option("--odometry", o->odometry,
                  "With --relations: the raw odometry (a CARMEN log or a TUM file) that places "
                  "relation stamps the estimate lacks")
      ->check(CLI::ExistingFile);
  sub->add_option("--align", o->align, "Alignment before ATE and RPE (Umeyama: SE3 or Sim3)")
      ->check(CLI::IsMember({"none", "rigid", "sim"}))
      ->capture_default_str()
      ->excludes(rel);
  const auto forms = CLI::IsMember({"auto", "kitti", "tum"});
  sub->add_option("--est-format", o->est_format, "Estimate's form (auto: from the line length)")
      ->check(forms)
      ->capture_default_str();
  sub->add_option("--ref-format", o->ref_format, "Reference's form (auto: from the line length)")
      ->check(forms)
      ->capture_default_str()
      ->excludes(rel);
  sub->add_option(
         "--max-time-diff", o->max_time_diff,
         "Largest stamp difference (s) pairing poses by time or finding a relation's poses")
      ->check(kFiniteNonNegative)
      ->capture_default_str();
  sub->add_flag("--per-frame", o->per_frame, "Also print the RPE of every frame (table format)");
  addFormatOption(*sub, o->format, {"table", "json"});
  sub->callback([o, sub] {
    if (o->reference.empty() == o->relations.empty())
      throw UsageError("evaluate needs --reference REF or --relations FILE");
    // --per-frame adds a table of the RPE of every frame: JSON always has it, relations none
    refuseIgnored(*sub, "--per-frame", o->relations.empty() && o->format == "table",
                  o->relations.empty() ? "with --format json: the JSON always holds the RPE of "
                                         "every frame (rpe.per_frame)"
                                       : "with --relations: the relation metric has no frames");
    refuseIgnored(*sub, "--odometry", !o->relations.empty(), "without --relations");
    emit(o->relations.empty() ? runReference(*o, *sub) : runRelations(*o), "");
  });
}

}  // namespace metricmap::cli
