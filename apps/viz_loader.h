#pragma once
/// \file viz_loader.h
/// \brief The drawing module, loaded on first use: commands that draw nothing start without
/// VTK's rendering libraries (and what they pull in: OpenGL, X11, MPI).

#include "metricmap/viz/module.h"

namespace metricmap::cli {

/// \brief libmetricmap_viz.so beside the executable (build tree) or in the installed library
/// directory. \throws std::runtime_error naming what is missing
const viz::Module& drawingModule();

}  // namespace metricmap::cli
