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

}  // namespace metricmap::cli
