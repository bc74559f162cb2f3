#pragma once
/// \file declared_config.h
/// \brief A configuration class bound from its declaration (common/parameter_schema.h): one
/// typed property per declared parameter (name, kind, doc, range and default from the library)
/// and `Config(**kwargs)` setting attributes by name. The value functions are the
/// configuration's own by-name accessors, which check what they must.

#include <deque>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>

#include "metricmap/common/parameter_schema.h"

namespace metricmap::python {

/// Properties for every parameter of `schema`, each checked for its Python type (a bool for a
/// switch, an int for counts, an int or float for reals) before `set` sees the value.
template <class C>
void bindDeclaredFields(pybind11::class_<C>& c, const std::vector<ParameterSpec>& schema,
                        double (*get)(const C&, const std::string&),
                        void (*set)(C&, const std::string&, double)) {
  namespace py = pybind11;
  static std::deque<std::string> docs;  // the docstrings live as long as the module
  for (const ParameterSpec& spec : schema) {
    const std::string name = spec.name;
    const ParameterKind kind = spec.kind;
    docs.push_back((spec.unit.empty() ? "" : spec.unit + ": ") + spec.doc + " (" +
                   parameterRule(spec) + "; default " + spec.default_text + ").");
    c.def_property(
        name.c_str(),
        [name, kind, get](const C& s) -> py::object {
          const double v = get(s, name);
          if (kind == ParameterKind::Switch) return py::bool_(v != 0.0);
          if (kind == ParameterKind::Count) return py::int_(static_cast<unsigned long long>(v));
          if (kind == ParameterKind::Integer) return py::int_(static_cast<long long>(v));
          return py::float_(v);
        },
        [name, kind, set](C& s, const py::object& v) {
          const bool is_bool = py::isinstance<py::bool_>(v);
          if (kind == ParameterKind::Switch) {
            if (!is_bool) throw py::type_error(name + " must be a bool");
            return set(s, name, v.cast<bool>() ? 1.0 : 0.0);
          }
          const bool whole = kind != ParameterKind::Real;
          if (is_bool ||
              !(py::isinstance<py::int_>(v) || (!whole && py::isinstance<py::float_>(v))))
            throw py::type_error(name + " must be " + (whole ? "an int" : "a number") + ", got " +
                                 std::string(py::str(py::type::of(v).attr("__name__"))));
          set(s, name, v.cast<double>());
        },
        docs.back().c_str());
  }
}

/// `C(**kwargs)`: the defaults, with the named attributes set (an unknown name a TypeError
/// naming it).
template <class C>
void bindKeywordConstructor(pybind11::class_<C>& c, const char* type_name) {
  namespace py = pybind11;
  static std::deque<std::string> docs;  // the docstrings live as long as the module
  const std::string type = type_name;
  docs.push_back(type + "(**kwargs): the defaults, with the named attributes set.");
  c.def(py::init([type](py::kwargs kwargs) {
          C config;
          py::object view = py::cast(&config, py::return_value_policy::reference);
          for (auto item : kwargs) {
            const std::string key = py::str(item.first);
            if (key.rfind('_', 0) == 0 || !py::hasattr(view, key.c_str()))
              throw py::type_error(type + " has no parameter '" + key + "'");
            view.attr(key.c_str()) = item.second;
          }
          return config;
        }),
        docs.back().c_str());
}

}  // namespace metricmap::python
