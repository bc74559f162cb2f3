#include "distance_query_csv.h"

#include <cmath>
#include <sstream>

namespace metricmap::cli {
namespace {

std::string number(double v) {
  if (std::isnan(v)) return "nan";
  std::ostringstream s;
  s.precision(9);
  s << v;
  return s.str();
}

}  // namespace

std::string queryCsv(const DistanceField& field, const std::vector<double>& xyz) {
  const std::size_t n = xyz.size() / 3;
  std::vector<double> d(n), g(3 * n);
  field.queryMany(xyz.data(), n, d.data(), g.data());
  std::string out = "x,y,z,distance,gx,gy,gz,inside\n";
  for (std::size_t i = 0; i < n; ++i) {
    out += number(xyz[3 * i]) + "," + number(xyz[3 * i + 1]) + "," + number(xyz[3 * i + 2]) + "," +
           number(d[i]) + "," + number(g[3 * i]) + "," + number(g[3 * i + 1]) + "," +
           number(g[3 * i + 2]) + "," + (std::isnan(d[i]) ? "0" : "1") + "\n";
  }
  return out;
}

}  // namespace metricmap::cli
