#include "metricmap/common/parameter_schema.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <stdexcept>

namespace metricmap {
namespace {

std::string shortest(double v) {
  char buf[40];
  for (int precision = 1; precision <= 17; ++precision) {
    std::snprintf(buf, sizeof buf, "%.*g", precision, v);
    if (std::strtod(buf, nullptr) == v) break;
  }
  // 1e+06 -> 1e6, 1e-05 -> 1e-5: exponents as a person writes them
  std::string text = buf;
  const std::size_t e = text.find('e');
  if (e != std::string::npos) {
    std::string mantissa = text.substr(0, e), exponent = text.substr(e + 1);
    const bool negative = exponent[0] == '-';
    if (exponent[0] == '+' || negative) exponent.erase(0, 1);
    while (exponent.size() > 1 && exponent[0] == '0') exponent.erase(0, 1);
    text = mantissa + "e" + (negative ? "-" : "") + exponent;
  }
  return text;
}

}  // namespace

std::string parameterRule(const ParameterSpec& spec) {
  if (spec.kind == ParameterKind::Switch) return "true or false";
  const ParameterRange& r = spec.range;
  const bool has_max = std::isfinite(r.max);
  std::string rule;
  if (has_max) {
    rule = std::string("in ") + (r.min_open ? "(" : "[") + shortest(r.min) + ", " +
           shortest(r.max) + (r.max_open ? ")" : "]");
  } else {
    rule = std::string(r.finite && spec.kind == ParameterKind::Real ? "finite and " : "") +
           (r.min_open ? "> " : ">= ") + shortest(r.min);
  }
  if (*r.note) rule += std::string(" ") + r.note;
  return rule;
}

bool parameterAccepts(const ParameterSpec& spec, double v) {
  if (spec.kind == ParameterKind::Switch) return v == 0.0 || v == 1.0;
  const ParameterRange& r = spec.range;
  if (std::isnan(v)) return false;
  if (std::isinf(v) && (r.finite || v < 0)) return false;
  if (spec.kind != ParameterKind::Real && std::isfinite(v) && v != std::floor(v)) return false;
  if (r.min_open ? !(v > r.min) : !(v >= r.min)) return false;
  if (std::isfinite(r.max) && (r.max_open ? !(v < r.max) : !(v <= r.max))) return false;
  return true;
}

void checkParameter(const ParameterSpec& spec, double value) {
  if (parameterAccepts(spec, value)) return;
  throw std::invalid_argument(spec.name + " must be " + parameterRule(spec) + ", got " +
                              shortest(value));
}

const char* parameterKindName(ParameterKind kind) {
  switch (kind) {
    case ParameterKind::Real:
      return "float";
    case ParameterKind::Count:
    case ParameterKind::Integer:
      return "int";
    case ParameterKind::Switch:
      return "bool";
  }
  return "float";
}

std::string nearestParameterName(const std::string& name, const std::vector<std::string>& names) {
  // Levenshtein distance, one row at a time
  auto edits = [](const std::string& a, const std::string& b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
      std::size_t diag = row[0];
      row[0] = i;
      for (std::size_t j = 1; j <= b.size(); ++j) {
        const std::size_t up = row[j];
        row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
        diag = up;
      }
    }
    return row[b.size()];
  };
  std::string nearest;
  std::size_t best = 4;  // within three edits
  for (const std::string& n : names) {
    const std::size_t d = edits(name, n);
    if (d < best) best = d, nearest = n;
  }
  return nearest;
}

}  // namespace metricmap
