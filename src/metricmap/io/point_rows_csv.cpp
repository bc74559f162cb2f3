#include "metricmap/io/point_rows_csv.h"

#include <cctype>
#include <sstream>
#include <stdexcept>

#include "metricmap/common/memory_budget.h"
#include "metricmap/common/parse_number.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/input_file.h"

namespace metricmap {
namespace {

std::vector<std::string> fieldsOf(const std::string& line) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : line) {
    if (c == ',' || c == ' ' || c == '\t' || c == '\r') {
      if (!cur.empty()) out.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  if (!cur.empty()) out.push_back(cur);
  return out;
}

}  // namespace

std::vector<double> readPointRows(const std::string& path) {
  const std::string text = readRegularFile(path, memoryBudget() / 8);
  std::istringstream in(text);
  std::vector<double> xyz;
  std::string line;
  std::size_t number_of_line = 0;
  bool first_row = true;  // only the first non-comment line may be a header
  while (std::getline(in, line)) {
    ++number_of_line;
    const std::vector<std::string> f = fieldsOf(line);
    if (f.empty() || f[0][0] == '#') continue;
    const std::string where = path + ":" + std::to_string(number_of_line);
    const bool numeric_start = std::isdigit(static_cast<unsigned char>(f[0][0])) ||
                               f[0][0] == '-' || f[0][0] == '+' || f[0][0] == '.';
    const bool header = first_row && !numeric_start && f[0] != "nan" && f[0] != "NaN" &&
                        f[0] != "inf" && f[0] != "Inf" && f[0] != "-inf";
    first_row = false;
    if (header) continue;
    if (f.size() != 2 && f.size() != 3)
      throw InputError(where + ": expected x,y or x,y,z, got " + std::to_string(f.size()) +
                       " fields");
    for (std::size_t a = 0; a < 3; ++a) {
      if (a == 2 && f.size() == 2) {
        xyz.push_back(0.0);
        continue;
      }
      try {
        xyz.push_back(parseFiniteDouble(f[a], where));
      } catch (const std::invalid_argument& e) {
        throw InputError(e.what());
      }
    }
  }
  if (xyz.empty()) throw InputError(path + ": no query point");
  return xyz;
}

}  // namespace metricmap
