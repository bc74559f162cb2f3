#pragma once
/// \file error_statistics.h
/// \brief Summaries of per-pose or per-relation errors, as evo and the SLAM benchmark give them.

#include <cstddef>
#include <vector>

namespace metricmap {

/// \brief evo's statistics of an error series: RMSE, mean, median (the mean of the two middle
/// values for an even count, as numpy's), population standard deviation (numpy's default, as
/// evo), min and max. All zero when `count` is 0.
struct ErrorStatistics {
  std::size_t count = 0;
  double rmse = 0.0;
  double mean = 0.0;
  double median = 0.0;
  double stddev = 0.0;
  double min = 0.0;
  double max = 0.0;
};

/// \brief The statistics of `values`.
ErrorStatistics summarizeErrors(const std::vector<double>& values);

/// \brief Mean and sample standard deviation (divided by n - 1, as Cartographer's
/// compute_relations_metrics gives the benchmark's "mean +/- std"); the deviation is 0 for one
/// value, both are 0 for none.
struct MeanAndStd {
  double mean = 0.0;
  double stddev = 0.0;
};

/// \brief Mean and sample standard deviation of `values`.
MeanAndStd meanAndSampleStd(const std::vector<double>& values);

}  // namespace metricmap
