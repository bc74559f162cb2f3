#include "svg_drawing.h"

#include "metricmap/viz/scan_view.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace metricmap::cli {
namespace {

std::string escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else if (c == '&')
      out += "&amp;";
    else
      out += c;
  }
  return out;
}

}  // namespace

std::string drawScanSvg(const pcl::PointCloud<pcl::PointXYZ>& scan,
                        const std::vector<LineSegment>& segments, const std::string& title) {
  const viz::ScanView v = viz::ScanView::fit(scan, 800.0);
  const double size = v.size, margin = v.margin, scale = v.scale;
  auto sx = [&](double x) { return v.px(x); };
  auto sy = [&](double y) { return v.py(y); };
  std::ostringstream os;
  os << std::fixed << std::setprecision(2);
  os << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << size << "\" height=\"" << size + 30
     << "\" viewBox=\"0 0 " << size << " " << size + 30 << "\">\n"
     << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
     << "<text x=\"10\" y=\"20\" font-family=\"sans-serif\" font-size=\"14\">" << escape(title)
     << "</text>\n";
  for (const auto& p : scan) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) continue;
    os << "<circle cx=\"" << sx(p.x) << "\" cy=\"" << sy(p.y) << "\" r=\"1.6\" fill=\"#777\"/>\n";
  }
  for (std::size_t k = 0; k < segments.size(); ++k) {
    const LineSegment& s = segments[k];
    const std::array<int, 3> rgb = viz::segmentColour(k);
    const std::string c = "rgb(" + std::to_string(rgb[0]) + "," + std::to_string(rgb[1]) + "," +
                          std::to_string(rgb[2]) + ")";
    os << "<line x1=\"" << sx(s.start.x()) << "\" y1=\"" << sy(s.start.y()) << "\" x2=\""
       << sx(s.end.x()) << "\" y2=\"" << sy(s.end.y()) << "\" stroke=\"" << c
       << "\" stroke-width=\"2.5\"/>\n";
    for (const Eigen::Vector2d& e : {s.start, s.end}) {
      os << "<rect x=\"" << sx(e.x()) - 3 << "\" y=\"" << sy(e.y()) - 3
         << "\" width=\"6\" height=\"6\" fill=\"none\" stroke=\"" << c << "\"/>\n";
    }
  }
  // Sensor and a 1 m scale bar.
  os << "<circle cx=\"" << sx(0) << "\" cy=\"" << sy(0) << "\" r=\"5\" fill=\"black\"/>\n";
  const double bar_y = size + 10;
  os << "<line x1=\"" << margin << "\" y1=\"" << bar_y << "\" x2=\"" << margin + scale << "\" y2=\""
     << bar_y << "\" stroke=\"black\" stroke-width=\"3\"/>\n"
     << "<text x=\"" << margin + scale + 8 << "\" y=\"" << bar_y + 5
     << "\" font-family=\"sans-serif\" font-size=\"13\">1 m</text>\n</svg>\n";
  return os.str();
}

}  // namespace metricmap::cli
