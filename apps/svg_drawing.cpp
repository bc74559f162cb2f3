#include "svg_drawing.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace metricmap::cli {
namespace {

std::string colour(std::size_t k) {
  // Golden-angle hues: neighbours get clearly different colours.
  const double h = std::fmod(static_cast<double>(k) * 137.508, 360.0);
  std::ostringstream os;
  os << "hsl(" << static_cast<int>(h) << ",85%,42%)";
  return os.str();
}

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
  double lo_x = 0, lo_y = 0, hi_x = 0, hi_y = 0;  // the sensor (origin) is always in view
  for (const auto& p : scan) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) continue;
    lo_x = std::min<double>(lo_x, p.x);
    hi_x = std::max<double>(hi_x, p.x);
    lo_y = std::min<double>(lo_y, p.y);
    hi_y = std::max<double>(hi_y, p.y);
  }
  const double span = std::max({hi_x - lo_x, hi_y - lo_y, 1.0});
  const double size = 800.0, margin = 40.0, scale = (size - 2 * margin) / span;
  auto sx = [&](double x) { return margin + (x - lo_x) * scale; };
  auto sy = [&](double y) { return size - margin - (y - lo_y) * scale; };  // y up
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
    const std::string c = colour(k);
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
