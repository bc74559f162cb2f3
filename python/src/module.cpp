// The compiled part of the `metricmap` Python package: one init function per binding file.
#include <pybind11/stl.h>

#include "arrays.h"

namespace metricmap::python {
void initBinPoints(py::module_& m);
void initCamera(py::module_& m);
void initDistance(py::module_& m);
void initCloudIo(py::module_& m);
void initGrid(py::module_& m);
void initHeightMap(py::module_& m);
void initLines(py::module_& m);
void initLocalization(py::module_& m);
void initLogOdds(py::module_& m);
void initMemory(py::module_& m);
void initOctree(py::module_& m);
void initOdometry(py::module_& m);
void initSequence(py::module_& m);
void initPoseGraph(py::module_& m);
void initSlam(py::module_& m);
void initSlam3D(py::module_& m);
void initEvaluation(py::module_& m);
void initPoseConversion(py::module_& m);
}  // namespace metricmap::python

PYBIND11_MODULE(_metricmap, m) {
  using namespace metricmap::python;
  m.doc() = "metricmap: metric maps from range data (compiled core; import metricmap).";
  m.attr("__version__") = METRICMAP_VERSION_STRING;
  registerExceptions(m);
  initMemory(m);
  initCloudIo(m);
  initGrid(m);
  initOctree(m);
  initBinPoints(m);
  initHeightMap(m);
  initCamera(m);
  initLines(m);
  initLocalization(m);
  initLogOdds(m);
  initDistance(m);
  initOdometry(m);
  initSequence(m);
  initPoseGraph(m);
  initSlam(m);
  initSlam3D(m);
  initEvaluation(m);
  initPoseConversion(m);
}
