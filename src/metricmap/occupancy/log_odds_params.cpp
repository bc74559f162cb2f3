#include "metricmap/occupancy/log_odds_params.h"

#include <sstream>
#include <stdexcept>
#include <string>

namespace metricmap {
namespace {

[[noreturn]] void bad(const std::string& name, double value, const std::string& rule) {
  std::ostringstream msg;
  msg << name << " must be " << rule << ", got " << value;
  throw std::invalid_argument(msg.str());
}

void probability(const std::string& name, double p) {
  if (!(p > 0.0 && p < 1.0)) bad(name, p, "a probability in (0, 1)");
}

}  // namespace

void validateLogOddsParams(const LogOddsParams& p) {
  if (!(std::isfinite(p.resolution) && p.resolution > 0.0))
    bad("resolution", p.resolution, "finite and > 0");
  // A hit must raise a voxel's occupancy and a miss lower it, or the map says nothing.
  if (!(p.prob_hit > 0.5 && p.prob_hit < 1.0)) bad("prob_hit", p.prob_hit, "in (0.5, 1)");
  if (!(p.prob_miss > 0.0 && p.prob_miss < 0.5)) bad("prob_miss", p.prob_miss, "in (0, 0.5)");
  probability("clamp_min", p.clamp_min);
  probability("clamp_max", p.clamp_max);
  probability("occupancy_threshold", p.occupancy_threshold);
  if (p.clamp_min > p.clamp_max) bad("clamp_min", p.clamp_min, "<= clamp_max");
  if (!(p.max_range >= kMinLogOddsMaxRange))
    bad("max_range", p.max_range, ">= 0.001 m (infinity: no cut)");
}

}  // namespace metricmap
