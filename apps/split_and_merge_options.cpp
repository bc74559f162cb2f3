#include "split_and_merge_options.h"

#include "cli_common.h"

namespace metricmap::cli {
namespace {

constexpr double kDeg = M_PI / 180.0;

}  // namespace

SplitAndMergeParams splitAndMergeParams(const SplitAndMergeOptions& o) {
  SplitAndMergeParams p;
  p.distance_threshold = o.distance;
  // Degrees are converted only when given, so the defaults stay the library's bit for bit.
  if (o.angle_deg != SplitAndMergeOptions{}.angle_deg) p.angle_threshold = o.angle_deg * kDeg;
  p.min_points = static_cast<std::size_t>(o.min_points);
  p.min_length = o.min_length;
  p.max_gap = o.max_gap;
  p.purge_order = o.purge == "after-merge" ? PurgeOrder::AfterMerge : PurgeOrder::BeforeMerge;
  p.chi2_split = o.chi2 > 0.0;
  if (p.chi2_split) p.chi2_threshold = o.chi2;
  p.range_sigma = o.range_sigma;
  if (o.bearing_sigma_deg != SplitAndMergeOptions{}.bearing_sigma_deg) {
    p.bearing_sigma = o.bearing_sigma_deg * kDeg;
  }
  return p;
}

void addSplitAndMergeOptions(CLI::App& app, SplitAndMergeOptions& o) {
  app.add_option("--distance-threshold", o.distance, "d_th: split distance, metres")
      ->check(kFinitePositive)
      ->capture_default_str();
  app.add_option("--angle-threshold-deg", o.angle_deg, "a_th: merge angle, degrees (0: no merge)")
      ->check(finiteIn(0.0, 180.0))
      ->capture_default_str();
  app.add_option("--min-points", o.min_points, "Purge segments with fewer points (0: off)")
      ->check(kCount)
      ->capture_default_str();
  app.add_option("--min-length", o.min_length, "Purge shorter segments, metres (0: off)")
      ->check(kFiniteNonNegative)
      ->capture_default_str();
  app.add_option("--max-gap", o.max_gap, "Split where neighbours are further apart (0: off)")
      ->check(kFiniteNonNegative)
      ->capture_default_str();
  app.add_option("--purge", o.purge, "When purge runs")
      ->check(CLI::IsMember({"before-merge", "after-merge"}))
      ->capture_default_str();
  app.add_option("--chi2", o.chi2,
                 "Split on d^2/var(d) > this (chi-square, 1 dof) instead of --distance-threshold")
      ->check(kFinitePositive);
  app.add_option("--range-sigma", o.range_sigma, "Range noise, metres")
      ->check(kFiniteNonNegative)
      ->capture_default_str();
  app.add_option("--bearing-sigma-deg", o.bearing_sigma_deg, "Bearing noise, degrees")
      ->check(finiteIn(0.0, 180.0))
      ->capture_default_str();
}

void checkSplitAndMergeOptions(const CLI::App& app, const SplitAndMergeOptions& o, bool json) {
  // Options that would change nothing in this run are refused.
  // A piece holds at least one point: --min-points 1 purges no more than 0.
  refuseIgnored(app, "--purge", o.min_points > 1 || o.min_length > 0.0,
                "with --min-points " + std::to_string(o.min_points) +
                    " and --min-length 0: nothing is purged (every segment has a point)");
  refuseIgnored(app, "--purge", o.angle_deg > 0.0,
                "with --angle-threshold-deg 0: there is no merge step to purge before or after");
  const bool sigmas_used = o.chi2 > 0.0 || json;
  for (const char* option : {"--range-sigma", "--bearing-sigma-deg"}) {
    refuseIgnored(app, option, sigmas_used,
                  "without --chi2 or --format json: the noise model shapes the chi-square split "
                  "test and the fits' covariances, which only JSON prints");
  }
}

}  // namespace metricmap::cli
