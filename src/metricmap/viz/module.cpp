#include "metricmap/viz/module.h"

#include <stdexcept>

#include <vtkObject.h>

#include "metricmap/viz/scan_png.h"
#include "metricmap/viz/view_scene.h"

namespace metricmap::viz {
namespace {

void show(const ViewRequest& r) {
  if (r.cloud == nullptr) throw std::invalid_argument("view: no cloud");
  const Scene scene =
      buildScene(*r.cloud, r.point_counts, r.boxes, r.options, r.segments, r.occupied, r.free);
  if (!r.screenshot.empty()) {
    writeScreenshot(scene, r.width, r.height, r.screenshot);
  } else {
    runInteractive(scene, r.width, r.height);
  }
}

}  // namespace
}  // namespace metricmap::viz

extern "C" const metricmap::viz::Module* metricmap_viz_module() {
  vtkObject::GlobalWarningDisplayOff();  // the module's callers report failures in one line
  static const metricmap::viz::Module module{
      metricmap::viz::kModuleAbi, &metricmap::viz::writeScanPng, &metricmap::viz::writeStudyPlot,
      &metricmap::viz::show};
  return &module;
}
