#include "metricmap/io/lines_json.h"

#include <fstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "metricmap/exceptions.h"
#include "metricmap/io/input_file.h"

namespace metricmap {

std::vector<Segment2D> readLineSegmentsJson(const std::string& path, long long scan) {
  requireRegularFile(path);
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open");
  try {
    // Deep nesting is refused while parsing (nlohmann's parser and destructor recurse).
    const nlohmann::json j =
        nlohmann::json::parse(in, [](int depth, nlohmann::json::parse_event_t, nlohmann::json&) {
          if (depth > 32) throw std::invalid_argument("nested deeper than 32 levels");
          return true;
        });
    for (const auto& s : j.at("scans")) {
      if (s.at("scan").get<long long>() != scan) continue;
      std::vector<Segment2D> out;
      for (const auto& seg : s.at("segments")) {
        out.push_back({Eigen::Vector2d(seg.at("start").at(0).get<double>(),
                                       seg.at("start").at(1).get<double>()),
                       Eigen::Vector2d(seg.at("end").at(0).get<double>(),
                                       seg.at("end").at(1).get<double>())});
      }
      return out;
    }
  } catch (const std::exception& e) {
    throw InputError(path + ": not the JSON of metricmap lines (" +
                     std::string(e.what()).substr(0, 60) + ")");
  }
  throw InputError(path + ": has no scan " + std::to_string(scan));
}

}  // namespace metricmap
