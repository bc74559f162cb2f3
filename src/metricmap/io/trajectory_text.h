#pragma once
/// \file trajectory_text.h
/// \brief Internal to the trajectory, stamp and relation readers (not installed API): the file
/// read whole with its size bounded, split into data lines and tokens, numbers checked.

#include <algorithm>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "metricmap/common/memory_budget.h"
#include "metricmap/common/parse_number.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/input_file.h"

namespace metricmap::detail {

/// \brief The whole regular file `path`, after checking that it and the values parsed from it
/// (at most one value of `value_bytes` per `min_bytes_per_value` bytes of text) fit the memory
/// budget. \throws InputError, CapacityError naming the path
inline std::string readBoundedText(const std::string& path, std::size_t min_bytes_per_value,
                                   std::size_t value_bytes) {
  std::string text = readRegularFile(path, memoryBudget());
  checkMemory(text.size() / min_bytes_per_value + 1, value_bytes, path + " (parsed values)");
  return text;
}

/// \brief Calls fn(line_number, tokens) for every line that is neither blank nor a comment
/// (first non-blank character '#'); tokens are separated by blanks, '\r' counts as blank.
template <typename Fn>
void forEachDataLine(const std::string& text, Fn&& fn) {
  constexpr std::string_view kBlank = " \t\r\v\f";
  std::vector<std::string_view> tokens;
  std::size_t pos = 0;
  for (std::size_t n = 1; pos < text.size(); ++n) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string::npos) end = text.size();
    const std::string_view line(text.data() + pos, end - pos);
    pos = end + 1;
    tokens.clear();
    for (std::size_t a = line.find_first_not_of(kBlank); a != std::string_view::npos;) {
      const std::size_t b = std::min(line.find_first_of(kBlank, a), line.size());
      tokens.push_back(line.substr(a, b - a));
      a = line.find_first_not_of(kBlank, b);
    }
    if (tokens.empty() || tokens.front().front() == '#') continue;
    fn(n, tokens);
  }
}

/// \brief "PATH: line N".
inline std::string lineWhere(const std::string& path, std::size_t line) {
  return path + ": line " + std::to_string(line);
}

/// \brief The token through parseFiniteDouble. \throws InputError "PATH: line N: 'T' is not ..."
inline double lineNumber(std::string_view token, const std::string& path, std::size_t line) {
  try {
    return parseFiniteDouble(token, lineWhere(path, line));
  } catch (const std::invalid_argument& e) {
    throw InputError(e.what());
  }
}

}  // namespace metricmap::detail
