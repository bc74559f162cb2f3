// The checked number parser: valid decimal forms equal strtod's value; every other form is refused.
#include <cfloat>
#include <climits>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "metricmap/common/parse_number.h"

namespace metricmap {
namespace {

std::string messageOf(const std::string& text) {
  try {
    parseFiniteDouble(text, "--opt");
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(ParseNumber, DecimalFormsMatchStrtod) {
  for (const char* t : {"0", "-0", "+0", "1", "-1.5", "+2.", ".5", "-.5", "1e3", "1E-3", "2.5e+10",
                        "0.0e999", "123456789012345678901234567890", "1.7976931348623157e308",
                        "2.2250738585072014e-308", "0.1", "1e-300"}) {
    EXPECT_EQ(parseFiniteDouble(t, "x"), std::strtod(t, nullptr)) << t;
  }
}

TEST(ParseNumber, RefusesNonDecimalForms) {
  for (const char* t :
       {"",  " 1", "1 ", "1x",   "0x10",  "inf", "-inf", "nan", "NaN", "infinity", "1e",   "e5",
        ".", "-",  "+",  "1..2", "1.2.3", "--1", "+-1",  "1e+", "1,5", "1e5.0",    "\xff", "1\t"}) {
    EXPECT_THROW(parseFiniteDouble(t, "x"), std::invalid_argument) << t;
  }
  EXPECT_THROW(parseFiniteDouble(std::string_view("1\0"
                                                  "2",
                                                  3),
                                 "x"),
               std::invalid_argument);
}

TEST(ParseNumber, RefusesOverflowAndUnderflow) {
  EXPECT_THROW(parseFiniteDouble("1e309", "x"), std::invalid_argument);
  EXPECT_THROW(parseFiniteDouble("-1e400", "x"), std::invalid_argument);
  EXPECT_THROW(parseFiniteDouble("1e-320", "x"), std::invalid_argument);  // subnormal
  EXPECT_THROW(parseFiniteDouble("1e-400", "x"), std::invalid_argument);  // underflows to 0
  EXPECT_EQ(parseFiniteDouble("0e-400", "x"), 0.0);                       // exact zero
}

TEST(ParseNumber, MessageNamesWhatAndText) {
  const std::string m = messageOf("abc");
  EXPECT_NE(m.find("--opt"), std::string::npos) << m;
  EXPECT_NE(m.find("'abc'"), std::string::npos) << m;
  EXPECT_NE(m.find("finite number"), std::string::npos) << m;
  // binary junk is escaped and long text shortened
  EXPECT_NE(messageOf("\x01z").find("\\x01z"), std::string::npos);
  EXPECT_LT(messageOf(std::string(5000, '9') + "x").size(), 120u);
}

TEST(ParseNumber, Integers) {
  EXPECT_EQ(parseInteger("42", "n", 0, 100), 42);
  EXPECT_EQ(parseInteger("+7", "n", 0, 100), 7);
  EXPECT_EQ(parseInteger("-3", "n", -5, 5), -3);
  EXPECT_EQ(parseInteger("9223372036854775807", "n", LLONG_MIN, LLONG_MAX), LLONG_MAX);
  EXPECT_EQ(parseInteger("-9223372036854775808", "n", LLONG_MIN, LLONG_MAX), LLONG_MIN);
  for (const char* t : {"", "-", "1.0", "1e3", "0x10", " 1", "1 ", "abc", "+-1",
                        "9223372036854775808", "999999999999999999999"}) {
    EXPECT_THROW(parseInteger(t, "n", LLONG_MIN, LLONG_MAX), std::invalid_argument) << t;
  }
  EXPECT_THROW(parseInteger("101", "n", 0, 100), std::invalid_argument);
  EXPECT_THROW(parseInteger("-1", "n", 0, 100), std::invalid_argument);
  try {
    parseInteger("101", "--count", 1, 100);
    FAIL();
  } catch (const std::invalid_argument& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("--count"), std::string::npos);
    EXPECT_NE(m.find("101"), std::string::npos);
    EXPECT_NE(m.find("[1, 100]"), std::string::npos);
  }
}

TEST(ParseNumber, Lists) {
  EXPECT_EQ(parseDoubleList("0.1,1,2.5", "z"), (std::vector<double>{0.1, 1.0, 2.5}));
  EXPECT_EQ(parseDoubleList("3", "z"), (std::vector<double>{3.0}));
  EXPECT_EQ(parseDoubleList("1x2", "z", 'x'), (std::vector<double>{1.0, 2.0}));
  for (const char* t : {"", ",", ",1", "1,", "1,,2", "1, 2", "1,nan", "1,inf", "1,1e999"}) {
    EXPECT_THROW(parseDoubleList(t, "z"), std::invalid_argument) << t;
  }
}

}  // namespace metricmap
