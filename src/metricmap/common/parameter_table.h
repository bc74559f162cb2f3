#pragma once
/// \file parameter_table.h
/// \brief A configuration aggregate's fields declared once, with the operations every
/// configuration needs by name: its schema (ParameterSpec with the default), its values as
/// numbers and as text that reads back exactly, setting from text or number (kind checked),
/// and the declared ranges checked. A command's --set, a Python dict and a docs table all go
/// through one table per configuration.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "metricmap/common/format_number.h"
#include "metricmap/common/parameter_schema.h"
#include "metricmap/common/parse_number.h"

namespace metricmap {

/// \brief The member a declared field lives in.
template <class C>
using ParameterMember = std::variant<double C::*, std::size_t C::*, int C::*, bool C::*>;

/// \brief One declared field of C.
template <class C>
struct ParameterField {
  const char* name;
  ParameterMember<C> member;
  const char* unit;  ///< "m", "deg", "s", "" for plain numbers
  ParameterRange range;
  const char* doc;  ///< one line
};

/// \brief Every field of C, declared once. `what` names the configuration in messages
/// ("unknown WHAT parameter 'x'").
template <class C>
class ParameterTable {
 public:
  ParameterTable(std::string what, std::vector<ParameterField<C>> fields)
      : what_(std::move(what)), fields_(std::move(fields)) {}

  std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const ParameterField<C>& f : fields_) out.emplace_back(f.name);
    return out;
  }

  /// The declarations in field order, each with C()'s value as its default.
  std::vector<ParameterSpec> schema() const {
    const C defaults{};
    std::vector<ParameterSpec> out;
    for (const ParameterField<C>& f : fields_) out.push_back(spec(f, defaults));
    return out;
  }

  /// The declaration of `name`. \throws std::invalid_argument for an unknown name
  ParameterSpec spec(const std::string& name) const { return spec(find(name), C{}); }

  /// \throws std::invalid_argument "NAME must be RULE, got VALUE" for the first field outside
  /// its declared range.
  void checkRanges(const C& config) const {
    for (const ParameterField<C>& f : fields_) checkParameter(spec(f, C{}), valueOf(config, f));
  }

  /// The value as a number (switches 0 or 1). \throws std::invalid_argument for an unknown name
  double value(const C& config, const std::string& name) const {
    return valueOf(config, find(name));
  }

  /// The value as text that setText reads back exactly.
  std::string text(const C& config, const std::string& name) const {
    return textOf(config, find(name));
  }

  /// Set from a number, checked for the field's kind only (a switch 0 or 1, a count a whole
  /// number that fits). \throws std::invalid_argument naming the parameter
  void setValue(C& config, const std::string& name, double v) const {
    const ParameterField<C>& f = find(name);
    const ParameterKind kind = kindOf(f);
    if (kind == ParameterKind::Switch && v != 0.0 && v != 1.0)
      throw std::invalid_argument(std::string(f.name) + " must be true or false");
    if (kind == ParameterKind::Count || kind == ParameterKind::Integer) {
      const double lo = kind == ParameterKind::Count ? 0.0 : -2147483648.0;
      const double hi = 2147483647.0;
      if (!(v == std::floor(v) && v >= lo && v <= hi))
        throw std::invalid_argument(std::string(f.name) + " must be a whole number in [" +
                                    formatNumber(lo) + ", " + formatNumber(hi) + "], got " +
                                    formatNumber(v));
    }
    if (auto d = std::get_if<double C::*>(&f.member))
      config.** d = v;
    else if (auto n = std::get_if<std::size_t C::*>(&f.member))
      config.** n = static_cast<std::size_t>(v);
    else if (auto i = std::get_if<int C::*>(&f.member))
      config.** i = static_cast<int>(v);
    else
      config.*std::get<bool C::*>(f.member) = v != 0.0;
  }

  /// Set from text: a finite number, a whole number for counts, true/false for switches.
  /// \throws std::invalid_argument naming the parameter
  void setText(C& config, const std::string& name, const std::string& value) const {
    const ParameterField<C>& f = find(name);
    switch (kindOf(f)) {
      case ParameterKind::Switch:
        if (value != "true" && value != "false")
          throw std::invalid_argument(name + ": '" + quoteForMessage(value) +
                                      "' is not true or false");
        return setValue(config, name, value == "true" ? 1.0 : 0.0);
      case ParameterKind::Real:
        return setValue(config, name, parseFiniteDouble(value, name));
      default:
        return setValue(config, name,
                        static_cast<double>(parseInteger(
                            value, name, kindOf(f) == ParameterKind::Count ? 0 : -2147483648LL,
                            std::numeric_limits<std::int32_t>::max())));
    }
  }

  /// \throws std::invalid_argument "unknown WHAT parameter 'x' (did you mean y?)"
  const ParameterField<C>& find(const std::string& name) const {
    for (const ParameterField<C>& f : fields_)
      if (name == f.name) return f;
    std::string msg = "unknown " + what_ + " parameter '" + quoteForMessage(name) + "'";
    const std::string near = nearestParameterName(name, names());
    if (!near.empty()) msg += " (did you mean " + near + "?)";
    throw std::invalid_argument(msg);
  }

 private:
  static ParameterKind kindOf(const ParameterField<C>& f) {
    if (std::holds_alternative<bool C::*>(f.member)) return ParameterKind::Switch;
    if (std::holds_alternative<std::size_t C::*>(f.member)) return ParameterKind::Count;
    if (std::holds_alternative<int C::*>(f.member)) return ParameterKind::Integer;
    return ParameterKind::Real;
  }

  static double valueOf(const C& c, const ParameterField<C>& f) {
    if (auto d = std::get_if<double C::*>(&f.member)) return c.**d;
    if (auto n = std::get_if<std::size_t C::*>(&f.member)) return static_cast<double>(c.**n);
    if (auto i = std::get_if<int C::*>(&f.member)) return c.**i;
    return c.*std::get<bool C::*>(f.member) ? 1.0 : 0.0;
  }

  static std::string textOf(const C& c, const ParameterField<C>& f) {
    if (kindOf(f) == ParameterKind::Switch) return valueOf(c, f) != 0.0 ? "true" : "false";
    return formatNumber(valueOf(c, f));  // the shortest text that reads back exactly
  }

  static ParameterSpec spec(const ParameterField<C>& f, const C& defaults) {
    return {f.name, kindOf(f), f.unit, f.range, f.doc, textOf(defaults, f)};
  }

  std::string what_;
  std::vector<ParameterField<C>> fields_;
};

}  // namespace metricmap
