#pragma once
/// \file table.h
/// \brief A small text table rendered as aligned columns, Markdown or CSV.

#include <string>
#include <vector>

namespace metricmap::cli {

enum class TableStyle { Aligned, Markdown, Csv };

/// \brief Rows of strings under a header; numbers are formatted by the caller.
class Table {
 public:
  explicit Table(std::vector<std::string> header) : header_(std::move(header)) {}
  void addRow(std::vector<std::string> row) { rows_.push_back(std::move(row)); }
  std::string render(TableStyle style) const;

 private:
  std::vector<std::string> header_;
  std::vector<std::vector<std::string>> rows_;
};

/// \brief Fixed-point with `decimals` digits.
std::string fixed(double value, int decimals);

/// \brief fixed(value, 3) when that shows the value to 6 significant digits (0.050), else the
/// value with 6 significant digits (1e-07, 0.0015): a tiny size never prints as 0.000.
std::string readable(double value);

}  // namespace metricmap::cli
