#include "metricmap/io/trajectory_relations.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <utility>

#include "metricmap/common/parse_number.h"
#include "metricmap/common/rigid_transform.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/trajectory_text.h"

namespace metricmap {

std::vector<PoseRelation> readRelations(const std::string& path) {
  // The shortest relation line: "0 0 0 0 0 0 0 0\n", 16 bytes.
  const std::string text = detail::readBoundedText(path, 16, sizeof(PoseRelation));
  std::vector<PoseRelation> relations;
  // each pair of stamps once, in either order: the line that named it first
  std::map<std::pair<double, double>, std::size_t> pairs;
  detail::forEachDataLine(text, [&](std::size_t n, const std::vector<std::string_view>& tokens) {
    if (tokens.size() != 8) {
      throw InputError(detail::lineWhere(path, n) + " has " + std::to_string(tokens.size()) +
                       " values, not 8 (t1 t2 x y z roll pitch yaw)");
    }
    double v[8];
    for (int i = 0; i < 8; ++i) v[i] = detail::lineNumber(tokens[i], path, n);
    const Eigen::Vector3d t(v[2], v[3], v[4]);
    if (!(t.cwiseAbs().maxCoeff() <= kMaxTranslation)) {
      std::ostringstream os;
      os << detail::lineWhere(path, n) << ": translation beyond " << kMaxTranslation << " m";
      throw InputError(os.str());
    }
    for (int i = 5; i < 8; ++i) {
      if (!(std::abs(v[i]) <= kMaxAngle)) {
        std::ostringstream os;
        os << detail::lineWhere(path, n) << ": "
           << (i == 5   ? "roll"
               : i == 6 ? "pitch"
                        : "yaw")
           << " '" << quoteForMessage(tokens[i]) << "' is beyond " << kMaxAngle << " rad";
        throw InputError(os.str());
      }
    }
    if (v[0] == v[1]) {
      throw InputError(detail::lineWhere(path, n) + ": t1 and t2 are the same stamp ('" +
                       quoteForMessage(tokens[0]) + "'): a relation joins two poses");
    }
    const auto [it, fresh] = pairs.emplace(std::minmax(v[0], v[1]), n);
    if (!fresh) {
      throw InputError(detail::lineWhere(path, n) + ": the stamps '" + quoteForMessage(tokens[0]) +
                       "' and '" + quoteForMessage(tokens[1]) + "' are related again (line " +
                       std::to_string(it->second) + "): a relation given twice would count twice");
    }
    PoseRelation r;
    r.stamp1 = v[0];
    r.stamp2 = v[1];
    r.relative.linear() = (Eigen::AngleAxisd(v[7], Eigen::Vector3d::UnitZ()) *
                           Eigen::AngleAxisd(v[6], Eigen::Vector3d::UnitY()) *
                           Eigen::AngleAxisd(v[5], Eigen::Vector3d::UnitX()))
                              .toRotationMatrix();
    r.relative.translation() = t;
    relations.push_back(r);
  });
  if (relations.empty()) throw InputError(path + ": no relations (every line blank or a comment)");
  return relations;
}

}  // namespace metricmap
