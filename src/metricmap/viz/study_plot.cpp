#include "metricmap/viz/study_plot.h"

#include "metricmap/io/atomic_file.h"
#include "metricmap/io/output_set.h"
#include "metricmap/viz/vtk_png.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

#include <unistd.h>
#include <vtkAxis.h>
#include <vtkChartMatrix.h>
#include <vtkChartXY.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkPlot.h>
#include <vtkRenderWindow.h>
#include <vtkSVGExporter.h>
#include <vtkStringArray.h>
#include <vtkTable.h>
#include <vtkTextProperty.h>
#include <vtkWindowToImageFilter.h>

namespace metricmap::viz {
namespace {

const unsigned char kColours[][3] = {{60, 110, 200}, {220, 90, 40}, {70, 160, 80}, {150, 80, 170}};

}  // namespace

bool spansOrdersOfMagnitude(const PlotPanel& panel, double ratio) {
  double lo = 0.0, hi = 0.0;
  for (const auto& series : panel.series) {
    for (double v : series.second) {
      if (!(v > 0.0)) continue;
      lo = lo == 0.0 ? v : std::min(lo, v);
      hi = std::max(hi, v);
    }
  }
  return lo > 0.0 && hi > ratio * lo;
}

void writeStudyPlot(const std::string& path, const std::vector<std::string>& categories,
                    const std::vector<PlotPanel>& panels) {
  const char* display = std::getenv("DISPLAY");
  if (display == nullptr || *display == '\0') {
    throw std::runtime_error(path + ": plotting needs an X display (run under xvfb-run -a)");
  }
  const bool svg = path.size() > 4 && path.compare(path.size() - 4, 4, ".svg") == 0;
  const int rows = static_cast<int>((panels.size() + 1) / 2);
  vtkNew<vtkContextView> view;
  view->GetRenderWindow()->SetOffScreenRendering(1);
  view->GetRenderWindow()->SetSize(1400, 560 * rows);
  vtkNew<vtkChartMatrix> matrix;
  view->GetScene()->AddItem(matrix);
  matrix->SetSize(vtkVector2i(2, rows));
  // room below each chart for its slanted category names, and left of the first
  matrix->SetBorders(110, 130, 30, 30);
  matrix->SetGutter(vtkVector2f(130.0f, 170.0f));
  vtkNew<vtkDoubleArray> ticks;
  vtkNew<vtkStringArray> labels;
  for (std::size_t c = 0; c < categories.size(); ++c) {
    ticks->InsertNextValue(static_cast<double>(c));
    labels->InsertNextValue(categories[c]);
  }
  for (std::size_t p = 0; p < panels.size(); ++p) {
    vtkChart* chart =
        matrix->GetChart(vtkVector2i(static_cast<int>(p % 2), rows - 1 - static_cast<int>(p / 2)));
    auto* xy = vtkChartXY::SafeDownCast(chart);
    chart->SetTitle(panels[p].title);
    chart->GetTitleProperties()->SetFontSize(16);
    chart->SetShowLegend(true);
    const bool log_scale = panels[p].log_scale || spansOrdersOfMagnitude(panels[p]);
    if (log_scale) chart->SetTitle(panels[p].title + " (log scale)");
    vtkNew<vtkTable> table;
    vtkNew<vtkDoubleArray> x;
    x->SetName("x");
    for (std::size_t c = 0; c < categories.size(); ++c) x->InsertNextValue(static_cast<double>(c));
    table->AddColumn(x);
    for (const auto& [name, values] : panels[p].series) {
      vtkNew<vtkDoubleArray> col;
      col->SetName(name.c_str());
      // a log scale as log10 of the values on a linear axis labelled in powers of ten (VTK's own
      // log axis falls back to linear for bars, whose base is 0); values below 1 drawn as 1
      for (double v : values) col->InsertNextValue(log_scale ? std::log10(std::max(v, 1.0)) : v);
      table->AddColumn(col);
    }
    for (std::size_t s = 0; s < panels[p].series.size(); ++s) {
      vtkPlot* bar = chart->AddPlot(vtkChart::BAR);
      bar->SetInputData(table, 0, static_cast<vtkIdType>(s + 1));
      const unsigned char* c = kColours[s % 4];
      bar->SetColor(c[0], c[1], c[2], 255);
    }
    if (xy != nullptr) xy->SetBarWidthFraction(0.8f);
    vtkAxis* bottom = chart->GetAxis(vtkAxis::BOTTOM);
    bottom->SetCustomTickPositions(ticks, labels);
    bottom->SetTitle("");
    // slanted names hang below the axis from their tick (right end at the tick), clear of the bars
    bottom->GetLabelProperties()->SetOrientation(30);
    bottom->GetLabelProperties()->SetJustificationToRight();
    bottom->GetLabelProperties()->SetVerticalJustificationToTop();
    bottom->GetLabelProperties()->SetFontSize(10);
    vtkAxis* left = chart->GetAxis(vtkAxis::LEFT);
    left->SetTitle("");
    if (log_scale) {
      double top = 0.0;
      for (const auto& series : panels[p].series)
        for (double v : series.second) top = std::max(top, std::log10(std::max(v, 1.0)));
      vtkNew<vtkDoubleArray> powers;
      vtkNew<vtkStringArray> names;
      for (int e = 0; e <= static_cast<int>(std::ceil(top)); ++e) {
        powers->InsertNextValue(e);
        names->InsertNextValue(e < 4 ? std::to_string(static_cast<int>(std::pow(10, e)))
                                     : "1e" + std::to_string(e));
      }
      left->SetCustomTickPositions(powers, names);
      left->SetRange(0.0, std::ceil(top));
      left->SetBehavior(vtkAxis::FIXED);
    }
  }
  view->GetRenderWindow()->Render();
  if (!svg) {
    vtkNew<vtkWindowToImageFilter> grab;
    grab->SetInput(view->GetRenderWindow());
    grab->Update();
    writeVtkPng(grab->GetOutputPort(), path);
    return;
  }
  checkOutputPath(path);
  const std::string tmp = temporaryPathFor(path);
  vtkNew<vtkSVGExporter> exporter;
  exporter->SetRenderWindow(view->GetRenderWindow());
  exporter->SetFileName(tmp.c_str());
  exporter->Write();
  if (access(tmp.c_str(), R_OK) != 0) {
    discardTemporary(tmp);
    throw std::runtime_error(path + ": cannot write the plot");
  }
  commitTemporary(tmp, path);
}

}  // namespace metricmap::viz
