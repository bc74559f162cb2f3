// The declared configurations: every range a declaration states is the one its validator
// enforces (just outside refused naming the field, closed ends accepted), values read back as
// text exactly, and unknown names get the nearest known one.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "metricmap/common/format_number.h"
#include "metricmap/common/parameter_schema.h"
#include "metricmap/localization/localizer_2d_parameters.h"
#include "metricmap/slam3d/slam3d_config.h"

namespace metricmap {
namespace {

/// One configuration seen through its by-name functions.
struct Declared {
  std::string what;
  std::vector<ParameterSpec> schema;
  std::function<void(const std::string&, const std::string&)> setAndValidate;  // on defaults
  std::function<std::string(const std::string&)> defaultText;
};

Declared localizer() {
  return {"Localizer2DConfig", localizer2DParameterSchema(),
          [](const std::string& n, const std::string& v) {
            Localizer2DConfig c;
            if (n == "min_range") c.max_range = 1e4;  // keep max_range > min_range true
            setLocalizer2DParameter(c, n, v);
            validateLocalizer2DConfig(c);
          },
          [](const std::string& n) { return localizer2DParameter(Localizer2DConfig(), n); }};
}

Declared slam3d() {
  return {
      "Slam3DConfig", slam3DParameterSchema(),
      [](const std::string& n, const std::string& v) {
        Slam3DConfig c;
        if (n == "min_range") c.max_range = 1e9;
        if (n == "verify_fine_threshold") c.verify_coarse_threshold = 1e9;
        setSlam3DParameter(c, n, v);
        validateSlam3DConfig(c);
      },
      [](const std::string& n) { return formatNumber(slam3DParameterValue(Slam3DConfig(), n)); }};
}

// "NAME ..." thrown: the refusal names the field (its own rule, or the parse of its text).
bool refusedNaming(const Declared& d, const std::string& name, double v) {
  try {
    d.setAndValidate(name, formatNumber(v));
  } catch (const std::invalid_argument& e) {
    return std::string(e.what()).find(name) != std::string::npos;
  }
  return false;
}

// Accepted by its own rule: only another field's rule may refuse it (min_range at 1e4 meets
// max_range's "> min_range").
bool accepted(const Declared& d, const std::string& name, double v) {
  try {
    d.setAndValidate(name, formatNumber(v));
  } catch (const std::invalid_argument& e) {
    if (std::string(e.what()).rfind(name + " ", 0) != 0) return true;
    ADD_FAILURE() << name << "=" << formatNumber(v) << ": " << e.what();
    return false;
  }
  return true;
}

void checkRanges(const Declared& d) {
  ASSERT_FALSE(d.schema.empty());
  for (const ParameterSpec& p : d.schema) {
    SCOPED_TRACE(d.what + "." + p.name + " " + parameterRule(p));
    const bool whole = p.kind != ParameterKind::Real;
    const double lo = p.range.min, hi = p.range.max;
    const double step = whole ? 1.0 : 1e-6 * std::max(1.0, std::fabs(lo));
    EXPECT_TRUE(refusedNaming(d, p.name, p.range.min_open ? lo : lo - step));
    if (!p.range.min_open) EXPECT_TRUE(accepted(d, p.name, lo));
    if (std::isfinite(hi)) {
      const double hstep = whole ? 1.0 : 1e-6 * std::max(1.0, std::fabs(hi));
      EXPECT_TRUE(refusedNaming(d, p.name, p.range.max_open ? hi : hi + hstep));
      if (!p.range.max_open) EXPECT_TRUE(accepted(d, p.name, hi));
    } else if (p.kind == ParameterKind::Real && p.range.finite) {
      EXPECT_TRUE(refusedNaming(d, p.name, std::numeric_limits<double>::infinity()));
    }
    // the default is inside its own range and reads back as it is written
    EXPECT_TRUE(parameterAccepts(p, std::stod(p.default_text)));
    EXPECT_EQ(d.defaultText(p.name), p.default_text);
  }
}

TEST(ParameterTables, LocalizerRangesAreWhatValidationEnforces) { checkRanges(localizer()); }

TEST(ParameterTables, Slam3DRangesAreWhatValidationEnforces) { checkRanges(slam3d()); }

TEST(ParameterTables, RealValuesReadBackExactly) {
  Localizer2DConfig c;
  setLocalizer2DParameter(c, "global_min_score", "0.1234567890123456789");
  Localizer2DConfig back;
  setLocalizer2DParameter(back, "global_min_score", localizer2DParameter(c, "global_min_score"));
  EXPECT_EQ(back.global_min_score, c.global_min_score);
  EXPECT_EQ(c.global_min_score, 0.1234567890123456789);
}

TEST(ParameterTables, UnknownNamesGetTheNearestKnownOne) {
  const std::vector<std::string> names = {"track_min_score", "global_min_score", "max_range"};
  EXPECT_EQ(nearestParameterName("track_min_scor", names), "track_min_score");
  EXPECT_EQ(nearestParameterName("max_rnage", names), "max_range");
  EXPECT_EQ(nearestParameterName("resolution", names), "");
  Localizer2DConfig c;
  try {
    setLocalizer2DParameter(c, "globl_min_score", "0.5");
    FAIL() << "an unknown name was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(
        e.what(),
        "unknown localisation parameter 'globl_min_score' (did you mean global_min_score?)");
  }
}

TEST(ParameterTables, CountsRefuseFractionsAndNegatives) {
  Localizer2DConfig c;
  EXPECT_THROW(setLocalizer2DParameter(c, "lost_after_weak_scans", "2.5"), std::invalid_argument);
  EXPECT_THROW(setLocalizer2DParameter(c, "global_search_points", "-1"), std::invalid_argument);
  Slam3DConfig s;
  EXPECT_THROW(setSlam3DParameter(s, "loop_every", "1.5"), std::invalid_argument);
  EXPECT_EQ(s.loop_every, Slam3DConfig().loop_every);  // nothing changed by a refusal
}

}  // namespace
}  // namespace metricmap
