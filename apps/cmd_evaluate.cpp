// metricmap evaluate EST (--reference REF | --relations FILE): ATE, per-frame RPE and KITTI drift
// of an estimated trajectory against a reference one, or the relation metric of Kümmerle et al.
#include <memory>
#include <stdexcept>

#include "cli_common.h"
#include "commands.h"
#include "evaluate_report.h"
#include "metricmap/datasets/odometry_file.h"
#include "metricmap/evaluation/relation_error.h"
#include "metricmap/evaluation/trajectory_evaluation.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/trajectory.h"
#include "metricmap/io/trajectory_relations.h"

namespace metricmap::cli {
namespace {

struct EvaluateOptions {
  std::string estimate, reference, relations, odometry, align = "rigid", format = "table";
  std::string est_format = "auto", ref_format = "auto";
  double max_time_diff = 0.01;
  StepFailureLimits steps;
  bool per_frame = false;
};

LoadedTrajectory load(const std::string& path, const std::string& format) {
  LoadedTrajectory l;
  l.path = path;
  l.trajectory = readTrajectoryFile(path, parseTrajectoryFormat(format), &l.format);
  return l;
}

std::string runReference(const EvaluateOptions& o, const CLI::App& app) {
  const LoadedTrajectory est = load(o.estimate, o.est_format),
                         ref = load(o.reference, o.ref_format);
  EvaluationConfig config;
  config.alignment = parseAlignmentMode(o.align);
  config.max_time_diff = o.max_time_diff;
  config.steps = o.steps;
  TrajectoryEvaluation ev;
  try {
    ev = evaluateTrajectory(est.trajectory, ref.trajectory, config);
  } catch (const std::invalid_argument& e) {
    throw InputError(o.estimate + " against " + o.reference + ": " + e.what());
  }
  refuseIgnored(app, "--max-time-diff", ev.pairs.mode == PairingMode::Stamps,
                "here: the poses pair by index (a trajectory without time stamps)");
  return referenceReport(est, ref, ev, config, o.per_frame, o.format);
}

std::string runRelations(const EvaluateOptions& o) {
  const LoadedTrajectory est = load(o.estimate, o.est_format);
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
    odometry = readOdometry(o.odometry);
    if (!odometry.hasStamps())
      throw InputError(o.odometry +
                       ": no time stamps (KITTI form); --odometry needs a CARMEN "
                       "log or a TUM trajectory");
  }
  RelationError e;
  try {
    e = relationError(est.trajectory, relations, o.max_time_diff,
                      o.odometry.empty() ? nullptr : &odometry);
  } catch (const InputError&) {  // no relation measured: named with the files
    throw InputError(o.relations + ": none of its " + std::to_string(relations.size()) +
                     " relations has both stamps within " + num(o.max_time_diff) +
                     " s of a stamp of " + o.estimate +
                     (o.odometry.empty() ? "" : " or within the span of " + o.odometry));
  }
  return relationsReport(est, {o.relations, &relations, o.max_time_diff, o.odometry}, e, o.format);
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
  sub->add_option(
         "--step-max-m", o->steps.max_translation,
         "A step (pose i to i + 1) whose RPE translation exceeds this (m) counts as failed")
      ->check(kFinitePositive)
      ->capture_default_str()
      ->excludes(rel);
  sub->add_option("--step-max-deg", o->steps.max_rotation_deg,
                  "A step whose RPE rotation exceeds this (deg) counts as failed")
      ->check(kFinitePositive)
      ->capture_default_str()
      ->excludes(rel);
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
