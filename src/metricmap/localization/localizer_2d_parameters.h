#pragma once
/// \file localizer_2d_parameters.h
/// \brief Localizer2DConfig by name: every field as "name=value" text (a command line's --set, a
/// Python dict), checked as strictly as the rest of the toolkit's numbers.

#include <string>
#include <vector>

#include "metricmap/common/parameter_schema.h"
#include "metricmap/localization/localizer_2d_config.h"

namespace metricmap {

/// \brief Every parameter declared once: name, kind, unit, range, one-line doc and default, in
/// the order of Localizer2DConfig's fields. validateLocalizer2DConfig checks these ranges.
std::vector<ParameterSpec> localizer2DParameterSchema();

/// \brief The names setLocalizer2DParameter knows, in the order of Localizer2DConfig's fields.
std::vector<std::string> localizer2DParameterNames();

/// \brief The value of `name` in `config`, as text that setLocalizer2DParameter reads back.
/// \throws std::invalid_argument for an unknown name
std::string localizer2DParameter(const Localizer2DConfig& config, const std::string& name);

/// \brief Set `name` to `value` (a finite number; an integer for counts). Ranges are checked by
/// validateLocalizer2DConfig. \throws std::invalid_argument naming the parameter
void setLocalizer2DParameter(Localizer2DConfig& config, const std::string& name,
                             const std::string& value);

}  // namespace metricmap
