#include "metricmap/sequence/odometry_timing.h"

#include <algorithm>

namespace metricmap {

double medianFrameMs(const std::vector<OdometryFrame>& frames) {
  if (frames.empty()) return 0.0;
  std::vector<double> ms;
  ms.reserve(frames.size());
  for (const OdometryFrame& f : frames) ms.push_back(f.ms);
  std::sort(ms.begin(), ms.end());
  return ms[ms.size() / 2];
}

}  // namespace metricmap
