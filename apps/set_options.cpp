#include "set_options.h"

#include <algorithm>
#include <stdexcept>

#include "cli_common.h"
#include "metricmap/common/parse_number.h"

namespace metricmap::cli {

std::vector<std::string> applySetOptions(
    const CLI::App& app, const std::vector<std::string>& settings, const OwnOptions& own,
    const std::function<void(const std::string& name, const std::string& value)>& set) {
  std::vector<std::string> seen;
  for (const std::string& s : settings) {
    const std::size_t eq = s.find('=');
    if (eq == std::string::npos || eq == 0)
      throw UsageError("--set: '" + quoteForMessage(s) + "' is not NAME=VALUE");
    const std::string name = s.substr(0, eq);
    try {
      set(name, s.substr(eq + 1));
    } catch (const std::invalid_argument& e) {
      throw UsageError(std::string("--set: ") + e.what());
    }
    if (std::find(seen.begin(), seen.end(), name) != seen.end())
      throw UsageError("--set: " + name + " is given twice");
    seen.push_back(name);
    for (const auto& [field, option] : own)
      if (field == name && app.count(option) > 0)
        throw UsageError("--set " + name + " and " + option + " set the same parameter");
  }
  return seen;
}

void validateSetOptions(const std::function<void()>& validate) {
  try {
    validate();
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--set: ") + e.what());
  }
}

}  // namespace metricmap::cli
