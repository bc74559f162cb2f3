#pragma once
/// \file parse_number.h
/// \brief One checked parser for every number read from an option or a file.

#include <string>
#include <string_view>
#include <vector>

namespace metricmap {

/// \brief Parse a whole text as one finite decimal number.
///
/// Accepted: optional sign, digits with an optional '.', an optional exponent ("-1.5e3", ".5",
/// "+2."). Refused: empty text, spaces, hex, "inf", "nan", trailing garbage, values that overflow
/// to infinity, and values that underflow to a subnormal or zero unless the text is an exact zero.
/// \param text the number
/// \param what what the number is (an option name, a file and field), used in the message
/// \throws std::invalid_argument "WHAT: 'TEXT' is not a finite number"
double parseFiniteDouble(std::string_view text, std::string_view what);

/// \brief Parse a whole text as one decimal integer within [min, max] (optional sign, digits).
/// \throws std::invalid_argument naming what, the text and the range
long long parseInteger(std::string_view text, std::string_view what, long long min, long long max);

/// \brief Parse "a,b,c": every item with parseFiniteDouble; empty items and an empty list refused.
/// \throws std::invalid_argument naming what and the item
std::vector<double> parseDoubleList(std::string_view text, std::string_view what, char sep = ',');

/// \brief The text as it may appear in a one-line message: at most 40 characters, control and
/// non-ASCII bytes written as \\xHH.
std::string quoteForMessage(std::string_view text);

}  // namespace metricmap
