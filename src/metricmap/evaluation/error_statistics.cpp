#include "metricmap/evaluation/error_statistics.h"

#include <algorithm>
#include <cmath>

namespace metricmap {

ErrorStatistics summarizeErrors(const std::vector<double>& values) {
  ErrorStatistics s;
  s.count = values.size();
  if (values.empty()) return s;
  const double n = static_cast<double>(values.size());
  double sum = 0.0, sum_sq = 0.0;
  for (double v : values) {
    sum += v;
    sum_sq += v * v;
  }
  s.mean = sum / n;
  s.rmse = std::sqrt(sum_sq / n);
  double dev = 0.0;
  for (double v : values) dev += (v - s.mean) * (v - s.mean);
  s.stddev = std::sqrt(dev / n);
  std::vector<double> sorted = values;
  std::sort(sorted.begin(), sorted.end());
  const std::size_t mid = sorted.size() / 2;
  s.median = sorted.size() % 2 ? sorted[mid] : 0.5 * (sorted[mid - 1] + sorted[mid]);
  s.min = sorted.front();
  s.max = sorted.back();
  return s;
}

MeanAndStd meanAndSampleStd(const std::vector<double>& values) {
  MeanAndStd m;
  if (values.empty()) return m;
  double sum = 0.0;
  for (double v : values) sum += v;
  m.mean = sum / static_cast<double>(values.size());
  if (values.size() < 2) return m;
  double dev = 0.0;
  for (double v : values) dev += (v - m.mean) * (v - m.mean);
  m.stddev = std::sqrt(dev / static_cast<double>(values.size() - 1));
  return m;
}

}  // namespace metricmap
