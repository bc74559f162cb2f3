#pragma once
/// \file parameter_schema.h
/// \brief A configuration's fields declared once: name, kind, unit, range, one-line doc. The
/// library's validators check values against these declarations, and the command line, the
/// Python module and the docs take names, ranges and docs from them.

#include <string>
#include <vector>

namespace metricmap {

/// \brief What a parameter holds.
enum class ParameterKind { Real, Count, Integer, Switch };

/// \brief The values a parameter accepts: [min, max], each end open or closed; `finite` false
/// lets the upper end be +infinity (with the meaning `note` gives).
struct ParameterRange {
  double min = 0.0, max = 0.0;
  bool min_open = false, max_open = false;
  bool finite = true;
  const char* note = "";  ///< appended to the rule, e.g. "(infinity: no cut)"
};

/// \brief One declared field.
struct ParameterSpec {
  std::string name;
  ParameterKind kind = ParameterKind::Real;
  std::string unit;  ///< "m", "deg", "s", "" for plain numbers
  ParameterRange range;
  std::string doc;           ///< one line
  std::string default_text;  ///< the default as setParameter-style text
};

/// \brief "in (0.5, 1)", "finite and > 0", ">= 1", "> 0 (infinity: no cut)", "true or false".
std::string parameterRule(const ParameterSpec& spec);

/// \brief True when `value` is accepted by the spec's range (and kind: whole for counts).
bool parameterAccepts(const ParameterSpec& spec, double value);

/// \brief \throws std::invalid_argument "NAME must be RULE, got VALUE" unless accepted.
void checkParameter(const ParameterSpec& spec, double value);

/// \brief "kind" as the docs and the Python module name it: "float", "int", "bool".
const char* parameterKindName(ParameterKind kind);

/// \brief The nearest of `names` to `name` within three edits ("" when none is): the "did you
/// mean" of an unknown parameter.
std::string nearestParameterName(const std::string& name, const std::vector<std::string>& names);

}  // namespace metricmap
