#pragma once
/// \file cast_totals.h
/// \brief The totals of a casting job run as several processes (MPI ranks), from each one's.

#include <cstdint>
#include <functional>
#include <vector>

#include "metricmap/occupancy/scan_casting.h"

namespace metricmap {

/// \brief Element-wise collectives over the processes, the job's result on the root (identity
/// in one process).
struct CastTotalsCollectives {
  std::function<void(std::vector<std::uint64_t>&)> sum;
  std::function<void(std::vector<double>&)> max;
};

/// \brief The job's totals: counts summed, seconds the slowest process's; `insert_cpu_s` gets
/// the insert seconds summed over the processes (for the time per scan, to the nanosecond).
ScanCastTotals reduceCastTotals(const ScanCastTotals& local, const CastTotalsCollectives& c,
                                double& insert_cpu_s);

}  // namespace metricmap
