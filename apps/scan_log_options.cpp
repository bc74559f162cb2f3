#include "scan_log_options.h"

#include <iostream>
#include <stdexcept>

#include "cli_common.h"

namespace metricmap::cli {

void addScanLogOptions(CLI::App& app, ScanLogOptions& o) {
  app.add_option("--preset", o.preset, "Known log layout")->check(CLI::IsMember({"urg04lx-mines"}));
  ScanLineFormat& f = o.scan_format;
  auto generic = [&o](const char* name) {
    return [&o, name](const std::string&) {
      if (!o.generic) o.generic_option = name;
      o.generic = true;
    };
  };
  app.add_option("--skip-tokens", f.skip_tokens, "Tokens before the ranges")
      ->check(kCount)
      ->each(generic("--skip-tokens"));
  app.add_option("--count", f.count, "Ranges per scan")->check(kCount)->each(generic("--count"));
  app.add_option("--angle-min-deg", f.angle_min_deg, "Angle of beam 0")
      ->check(kFinite)
      ->each(generic("--angle-min-deg"));
  app.add_option("--angle-increment-deg", f.angle_increment_deg, "Angle between beams")
      ->check(kFinite)
      ->each(generic("--angle-increment-deg"));
  app.add_option("--range-scale", f.range_scale, "Raw range x scale = metres")
      ->check(kFinitePositive)
      ->each(generic("--range-scale"));
  app.add_option("--min-range", f.min_range, "Smaller ranges (m) are invalid")
      ->check(kFiniteNonNegative)
      ->each(generic("--min-range"));
  app.add_option("--max-range", f.max_range, "Larger ranges (m) are invalid")
      ->check(kFinite)
      ->each(generic("--max-range"));
}

ScanLog readScanLogOptions(const std::string& file, const ScanLogOptions& o, const CLI::App& app) {
  if (o.generic && !o.preset.empty()) {  // the preset would silently override the option
    throw UsageError(o.generic_option + ": --preset " + o.preset +
                     " sets the whole log layout; give --preset or the layout options, not both");
  }
  const ScanLineFormat& f = o.scan_format;
  if (o.generic && !(f.max_range > f.min_range)) {  // named as given: `1e1`, not `10.000000`
    const auto quoted = [&app](const char* option, double value) {
      const std::string text = givenText(app, option);
      return std::string(option) + " '" + (text.empty() ? plainNumber(value) : text) + "'";
    };
    throw UsageError(quoted("--min-range", f.min_range) + " must be below " +
                     quoted("--max-range", f.max_range) + ": no range would be valid");
  }
  if (o.generic && o.preset.empty()) {
    try {
      validateScanLineFormat(o.scan_format);  // option values: a usage error
    } catch (const std::invalid_argument& e) {
      throw CLI::ValidationError("scan format", e.what());
    }
  }
  const ScanLineFormat mines = urg04lxMinesFormat();
  const ScanLineFormat* layout =
      !o.preset.empty() ? &mines : (o.generic ? &o.scan_format : nullptr);
  ScanLog log = readScanLog(file, layout);
  for (const std::string& w : log.warnings) std::cerr << "warning: " << w << "\n";
  return log;
}

}  // namespace metricmap::cli
