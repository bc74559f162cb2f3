#include "metricmap/common/parse_number.h"

#include <cfloat>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <system_error>

namespace metricmap {
namespace {

bool isDigit(char c) { return c >= '0' && c <= '9'; }

[[noreturn]] void refuse(std::string_view text, std::string_view what, const std::string& why) {
  throw std::invalid_argument(std::string(what) + ": '" + quoteForMessage(text) + "' " + why);
}

/// \brief Checks the decimal grammar; tells whether some mantissa digit is not '0'.
bool decimalGrammar(std::string_view s, bool& nonzero_digit) {
  std::size_t i = 0;
  nonzero_digit = false;
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
  std::size_t digits = 0;
  while (i < s.size() && isDigit(s[i])) {
    nonzero_digit |= s[i] != '0';
    ++i;
    ++digits;
  }
  if (i < s.size() && s[i] == '.') {
    ++i;
    while (i < s.size() && isDigit(s[i])) {
      nonzero_digit |= s[i] != '0';
      ++i;
      ++digits;
    }
  }
  if (digits == 0) return false;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    std::size_t exp_digits = 0;
    while (i < s.size() && isDigit(s[i])) {
      ++i;
      ++exp_digits;
    }
    if (exp_digits == 0) return false;
  }
  return i == s.size();
}

}  // namespace

std::string quoteForMessage(std::string_view text) {
  constexpr std::size_t kMax = 40;
  std::string out;
  for (std::size_t i = 0; i < text.size() && i < kMax; ++i) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c >= 0x20 && c < 0x7f && c != '\\') {
      out += static_cast<char>(c);
    } else {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", c);
      out += buf;
    }
  }
  if (text.size() > kMax) out += "...";
  return out;
}

double parseFiniteDouble(std::string_view text, std::string_view what) {
  bool nonzero_digit = false;
  if (!decimalGrammar(text, nonzero_digit)) refuse(text, what, "is not a finite number");
  // from_chars is locale-independent; it takes no leading '+'.
  const std::string_view body = text[0] == '+' ? text.substr(1) : text;
  double value = 0.0;
  const auto [end, ec] = std::from_chars(body.data(), body.data() + body.size(), value);
  if (ec == std::errc::result_out_of_range) {
    refuse(text, what, "is not a finite number (out of range)");
  }
  if (ec != std::errc() || end != body.data() + body.size())
    refuse(text, what, "is not a finite number");
  if (!std::isfinite(value)) refuse(text, what, "is not a finite number (out of range)");
  if (nonzero_digit && std::fabs(value) < DBL_MIN)
    refuse(text, what, "is not a finite number (too close to zero to be represented)");
  return value;
}

long long parseInteger(std::string_view text, std::string_view what, long long min, long long max) {
  const std::string range =
      " (expected an integer in [" + std::to_string(min) + ", " + std::to_string(max) + "])";
  std::size_t i = 0;
  if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
  if (i == text.size()) refuse(text, what, "is not an integer" + range);
  for (std::size_t k = i; k < text.size(); ++k)
    if (!isDigit(text[k])) refuse(text, what, "is not an integer" + range);
  const std::string_view body = text[0] == '+' ? text.substr(1) : text;
  long long value = 0;
  const auto [end, ec] = std::from_chars(body.data(), body.data() + body.size(), value);
  if (ec != std::errc() || end != body.data() + body.size() || value < min || value > max)
    refuse(text, what, "is out of range" + range);
  return value;
}

std::vector<double> parseDoubleList(std::string_view text, std::string_view what, char sep) {
  if (text.empty()) refuse(text, what, "is an empty list");
  std::vector<double> values;
  std::size_t start = 0;
  while (true) {
    const std::size_t pos = text.find(sep, start);
    const std::string_view item =
        text.substr(start, pos == std::string_view::npos ? std::string_view::npos : pos - start);
    if (item.empty()) refuse(text, what, "has an empty item");
    values.push_back(parseFiniteDouble(item, what));
    if (pos == std::string_view::npos) break;
    start = pos + 1;
  }
  return values;
}

}  // namespace metricmap
