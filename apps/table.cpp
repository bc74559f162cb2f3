#include "table.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace metricmap::cli {
namespace {

std::string csvField(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) out += (c == '"') ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

}  // namespace

std::string fixed(double value, int decimals) {
  std::ostringstream os;
  os << std::fixed << std::setprecision(decimals) << value;
  return os.str();
}

std::string readable(double value) {
  const std::string three = fixed(value, 3);
  if (std::abs(std::stod(three) - value) <= 1e-6 * std::abs(value)) return three;
  std::ostringstream os;
  os << std::setprecision(6) << value;
  return os.str();
}

std::string Table::render(TableStyle style) const {
  std::ostringstream os;
  if (style == TableStyle::Csv) {
    auto line = [&](const std::vector<std::string>& r) {
      for (std::size_t i = 0; i < r.size(); ++i) os << (i ? "," : "") << csvField(r[i]);
      os << "\n";
    };
    line(header_);
    for (const auto& r : rows_) line(r);
    return os.str();
  }
  std::vector<std::size_t> width(header_.size(), 0);
  for (std::size_t i = 0; i < header_.size(); ++i) width[i] = header_[i].size();
  for (const auto& r : rows_) {
    for (std::size_t i = 0; i < r.size() && i < width.size(); ++i) {
      width[i] = std::max(width[i], r[i].size());
    }
  }
  const bool md = style == TableStyle::Markdown;
  auto line = [&](const std::vector<std::string>& r) {
    if (md) os << "| ";
    for (std::size_t i = 0; i < width.size(); ++i) {
      const std::string& cell = i < r.size() ? r[i] : std::string();
      if (i) os << (md ? " | " : "  ");
      os << (i == 0 ? std::left : std::right) << std::setw(static_cast<int>(width[i])) << cell;
    }
    os << (md ? " |" : "") << "\n";
  };
  line(header_);
  if (md) {
    os << "|";
    for (std::size_t i = 0; i < width.size(); ++i) {
      os << (i == 0 ? ":" : "-") << std::string(width[i], '-') << (i == 0 ? "-|" : ":|");
    }
    os << "\n";
  }
  for (const auto& r : rows_) line(r);
  return os.str();
}

}  // namespace metricmap::cli
