#include "metricmap/occupancy/log_odds_params.h"

#include <cstdio>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

#include "metricmap/occupancy/octomap_file_check.h"

namespace metricmap {
namespace {

[[noreturn]] void bad(const std::string& name, double value, const std::string& rule) {
  std::ostringstream msg;
  msg << name << " must be " << rule << ", got " << value;
  throw std::invalid_argument(msg.str());
}

}  // namespace

const std::vector<LogOddsField>& logOddsFields() {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const LogOddsParams d;
  auto field = [&d](const char* name, const char* unit, ParameterRange range, const char* doc,
                    double LogOddsParams::*member) {
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", d.*member);
    return LogOddsField{{name, ParameterKind::Real, unit, range, doc, text}, member};
  };
  // A hit must raise a voxel's occupancy and a miss lower it, or the map says nothing.
  static const std::vector<LogOddsField> fields = {
      // The cell edges a .bt/.ot file holds (its reader refuses others): a map is writable.
      field("resolution", "m", {kOctomapMinResolution, kOctomapMaxResolution}, "voxel (cell) edge",
            &LogOddsParams::resolution),
      field("prob_hit", "", {0.5, 1.0, true, true}, "P(occupied | hit), added at a beam's end",
            &LogOddsParams::prob_hit),
      field("prob_miss", "", {0.0, 0.5, true, true}, "P(occupied | miss), added along a beam",
            &LogOddsParams::prob_miss),
      field("clamp_min", "", {0.0, 1.0, true, true}, "lower clamping bound, as a probability",
            &LogOddsParams::clamp_min),
      field("clamp_max", "", {0.0, 1.0, true, true}, "upper clamping bound, as a probability",
            &LogOddsParams::clamp_max),
      field("occupancy_threshold", "", {0.0, 1.0, true, true},
            "occupied at this probability or more", &LogOddsParams::occupancy_threshold),
      // Far below 1 mm a cut beam's float direction underflows (its squared length is 0 below
      // ~1e-19 m), and no sensor measures a range shorter.
      field("max_range", "m",
            {kMinLogOddsMaxRange, kInf, false, false, false, "m (infinity: no cut)"},
            "beams are cut here and mark no hit", &LogOddsParams::max_range),
  };
  return fields;
}

void validateLogOddsParams(const LogOddsParams& p) {
  for (const LogOddsField& f : logOddsFields()) checkParameter(f.spec, p.*f.member);
  if (p.clamp_min > p.clamp_max) bad("clamp_min", p.clamp_min, "<= clamp_max");
}

}  // namespace metricmap
