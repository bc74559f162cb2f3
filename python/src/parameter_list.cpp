#include "parameter_list.h"

namespace py = pybind11;

namespace metricmap::python {

py::list parameterList(const std::vector<ParameterSpec>& schema) {
  py::list out;
  for (const ParameterSpec& p : schema) {
    py::dict d;
    d["name"] = p.name;
    d["kind"] = parameterKindName(p.kind);
    d["unit"] = p.unit;
    d["rule"] = parameterRule(p);
    d["min"] = p.range.min;
    d["max"] = p.range.max;
    d["min_open"] = p.range.min_open;
    d["max_open"] = p.range.max_open;
    d["default"] = p.default_text;
    d["doc"] = p.doc;
    out.append(d);
  }
  return out;
}

}  // namespace metricmap::python
