#pragma once
/// \file parameter_list.h
/// \brief A configuration's declaration (common/parameter_schema.h) as Python sees it: one dict
/// per parameter (name, kind, unit, rule, min, max, min_open, max_open, default, doc).

#include <vector>

#include <pybind11/pybind11.h>

#include "metricmap/common/parameter_schema.h"

namespace metricmap::python {

pybind11::list parameterList(const std::vector<ParameterSpec>& schema);

}  // namespace metricmap::python
