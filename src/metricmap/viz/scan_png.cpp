#include "metricmap/viz/scan_png.h"

#include <cstdio>
#include <stdexcept>

#include <unistd.h>
#include <vtkImageCanvasSource2D.h>
#include <vtkNew.h>

#include "metricmap/viz/scan_view.h"
#include "metricmap/viz/vtk_png.h"

namespace metricmap::viz {

void writeScanPng(const std::string& path, const pcl::PointCloud<pcl::PointXYZ>& scan,
                  const std::vector<LineSegment>& segments) {
  const ScanView v = ScanView::fit(scan, 800.0);
  const int w = static_cast<int>(v.size), h = static_cast<int>(v.size) + 30;
  // VTK images have y up: row 0 is the bottom; ScanView counts from the top.
  auto X = [&](double x) { return static_cast<int>(std::lround(v.px(x))); };
  auto Y = [&](double y) { return h - 1 - static_cast<int>(std::lround(v.py(y))); };

  vtkNew<vtkImageCanvasSource2D> canvas;
  canvas->SetScalarTypeToUnsignedChar();
  canvas->SetNumberOfScalarComponents(3);
  canvas->SetExtent(0, w - 1, 0, h - 1, 0, 0);
  canvas->SetDrawColor(255, 255, 255);
  canvas->FillBox(0, w - 1, 0, h - 1);
  canvas->SetDrawColor(110, 110, 110);
  for (const auto& p : scan) {
    if (std::isfinite(p.x) && std::isfinite(p.y)) {
      canvas->FillBox(X(p.x) - 1, X(p.x) + 1, Y(p.y) - 1, Y(p.y) + 1);
    }
  }
  for (std::size_t k = 0; k < segments.size(); ++k) {
    const std::array<int, 3> c = segmentColour(k);
    canvas->SetDrawColor(c[0], c[1], c[2]);
    const LineSegment& s = segments[k];
    for (int d = -1; d <= 1; ++d) {  // 3 px wide
      canvas->DrawSegment(X(s.start.x()) + d, Y(s.start.y()), X(s.end.x()) + d, Y(s.end.y()));
      canvas->DrawSegment(X(s.start.x()), Y(s.start.y()) + d, X(s.end.x()), Y(s.end.y()) + d);
    }
    for (const Eigen::Vector2d& e : {s.start, s.end}) {
      canvas->FillBox(X(e.x()) - 3, X(e.x()) + 3, Y(e.y()) - 3, Y(e.y()) + 3);
    }
  }
  canvas->SetDrawColor(0, 0, 0);
  canvas->DrawCircle(X(0), Y(0), 5);
  canvas->FillBox(X(0) - 2, X(0) + 2, Y(0) - 2, Y(0) + 2);
  const int bar_y = 12, bar_x0 = static_cast<int>(v.margin);
  canvas->FillBox(bar_x0, bar_x0 + static_cast<int>(std::lround(v.scale)), bar_y - 1, bar_y + 1);
  canvas->Update();

  writeVtkPng(canvas->GetOutputPort(), path);
}

}  // namespace metricmap::viz
