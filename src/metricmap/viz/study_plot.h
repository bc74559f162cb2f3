#pragma once
/// \file study_plot.h
/// \brief The study's figures as grouped bar charts (VTK charts), rendered offscreen to PNG or SVG.

#include <string>
#include <utility>
#include <vector>

namespace metricmap::viz {

/// \brief One chart: a title and named series, one value per x category.
struct PlotPanel {
  std::string title;
  /// Logarithmic value axis. writeStudyPlot also takes one for a panel whose positive values
  /// span more than two orders of magnitude (a linear axis would show the small bars as none).
  bool log_scale = false;
  std::vector<std::pair<std::string, std::vector<double>>> series;
};

/// \brief Do the panel's positive values span more than `ratio` (largest / smallest)?
bool spansOrdersOfMagnitude(const PlotPanel& panel, double ratio = 100.0);

/// \brief Draw the panels in a 2-column matrix sharing the x categories; .png or .svg by the
/// path's extension. Needs an X server (xvfb-run -a), like the viewer.
/// \throws std::runtime_error naming the file
void writeStudyPlot(const std::string& path, const std::vector<std::string>& categories,
                    const std::vector<PlotPanel>& panels);

}  // namespace metricmap::viz
