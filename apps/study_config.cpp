#include "study_config.h"

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "metricmap/common/parse_number.h"

namespace metricmap::cli {
namespace {

/// Through the checked parser; a value beyond float range is refused before the cast (UB).
bool parsePositive(const std::string& s, float& v) {
  double d = 0.0;
  try {
    d = parseFiniteDouble(s, "value");
  } catch (const std::invalid_argument&) {
    return false;
  }
  if (!(d > 0.0) || d > static_cast<double>(std::numeric_limits<float>::max())) return false;
  v = static_cast<float>(d);
  return v > 0.0f;
}

bool parseCount(const std::string& s, std::size_t& v) {
  if (s.empty() || s.find_first_not_of("0123456789") != std::string::npos) return false;
  try {
    v = static_cast<std::size_t>(parseInteger(s, "value", 0, 0xFFFFFFFFll));
  } catch (const std::invalid_argument&) {
    return false;
  }
  return true;
}

}  // namespace

std::string parseStudyConfig(const std::string& text, StudyConfig& out) {
  bool seen[3] = {false, false, false};
  // Items split by hand: getline would drop a trailing empty item ("...,max_points=100,").
  std::vector<std::string> items;
  for (std::size_t start = 0;;) {
    const std::size_t comma = text.find(',', start);
    items.push_back(
        text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  for (const std::string& item : items) {
    if (item.empty()) return "empty item in '" + quoteForMessage(text) + "'";
    const auto eq = item.find('=');
    if (eq == std::string::npos) return "'" + quoteForMessage(item) + "' is not key=value";
    const std::string key = item.substr(0, eq), value = item.substr(eq + 1);
    const int index = key == "cell_size"       ? 0
                      : key == "min_cell_size" ? 1
                      : key == "max_points"    ? 2
                                               : -1;
    if (index >= 0 && seen[index]) return "'" + key + "' is given twice";
    if (key == "cell_size") {
      if (!parsePositive(value, out.cell_size))
        return "cell_size must be a finite number > 0, got '" + quoteForMessage(value) + "'";
      seen[0] = true;
    } else if (key == "min_cell_size") {
      if (!parsePositive(value, out.min_cell_size))
        return "min_cell_size must be a finite number > 0, got '" + quoteForMessage(value) + "'";
      seen[1] = true;
    } else if (key == "max_points") {
      if (!parseCount(value, out.max_points))
        return "max_points must be a whole number from 0 to 4294967295, got '" +
               quoteForMessage(value) + "'";
      seen[2] = true;
    } else {
      return "unknown key '" + quoteForMessage(key) + "' (cell_size, min_cell_size, max_points)";
    }
  }
  if (!seen[0] || !seen[1] || !seen[2]) return "needs cell_size, min_cell_size and max_points";
  return std::string();
}

std::vector<StudyConfig> studyConfigs() {
  return {{1.0f, 1.0f, 100}, {0.5f, 0.5f, 100}, {2.0f, 1.0f, 200}};
}

}  // namespace metricmap::cli
