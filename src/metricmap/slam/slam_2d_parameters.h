#pragma once
/// \file slam_2d_parameters.h
/// \brief Slam2DConfig by name: every field as "name=value" text (a command line's --set, a
/// Python dict, a tuning script), checked as strictly as the rest of the toolkit's numbers.

#include <string>
#include <vector>

#include "metricmap/common/parameter_schema.h"
#include "metricmap/slam/slam_2d_config.h"

namespace metricmap {

/// \brief Every parameter declared once: name, kind, unit, range, one-line doc and default, in
/// the order of Slam2DConfig's fields (the final map's as "map_resolution", ...).
std::vector<ParameterSpec> slam2DParameterSchema();

/// \brief \throws std::invalid_argument "NAME must be RULE, got VALUE" for the first field
/// outside its declared range.
void checkSlam2DParameterRanges(const Slam2DConfig& config);

/// \brief The names setSlam2DParameter knows, in the order of Slam2DConfig's fields (the final
/// map's as "map_resolution", "map_prob_hit", ...).
std::vector<std::string> slam2DParameterNames();

/// \brief The value of `name` in `config`, as text that setSlam2DParameter reads back exactly.
/// \throws std::invalid_argument for an unknown name
std::string slam2DParameter(const Slam2DConfig& config, const std::string& name);

/// \brief Set `name` to `value` (a finite number; an integer for counts; "true"/"false" for
/// switches). The value is checked
/// only for its form here: validateSlam2DConfig checks the ranges of the whole configuration.
/// \throws std::invalid_argument naming the parameter: an unknown name (with the nearest known
/// one), a value that is not a number of the field's kind
void setSlam2DParameter(Slam2DConfig& config, const std::string& name, const std::string& value);

/// \brief The value of `name` as a number (switches 0 or 1, counts whole).
/// \throws std::invalid_argument for an unknown name
double slam2DParameterValue(const Slam2DConfig& config, const std::string& name);

/// \brief A parameter of the loop closure (loop_*, wide_*, branch_and_bound_depth): without loop
/// closure it has no effect, and giving it is refused.
bool isLoopClosureParameter(const std::string& name);

/// \brief Set `name` to `value`, checked only for the field's kind (a switch 0 or 1, a count a
/// whole number that fits): validateSlam2DConfig checks the ranges.
/// \throws std::invalid_argument naming the parameter
void setSlam2DParameterValue(Slam2DConfig& config, const std::string& name, double value);

}  // namespace metricmap
