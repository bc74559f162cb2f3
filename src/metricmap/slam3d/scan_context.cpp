#include "metricmap/slam3d/scan_context.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace metricmap {

void validateScanContextParams(const ScanContextParams& p) {
  if (p.rings < 1) throw std::invalid_argument("scan context rings must be >= 1");
  if (p.sectors < 4) throw std::invalid_argument("scan context sectors must be >= 4");
  if (!(p.max_radius > 0.0) || !std::isfinite(p.max_radius))
    throw std::invalid_argument("scan context max_radius must be finite and > 0");
  if (!std::isfinite(p.height_offset))
    throw std::invalid_argument("scan context height_offset must be finite");
}

ScanContext makeScanContext(const std::vector<Eigen::Vector3f>& points,
                            const ScanContextParams& p) {
  validateScanContextParams(p);
  ScanContext sc;
  sc.bins = Eigen::MatrixXf::Zero(p.rings, p.sectors);
  const double two_pi = 2.0 * M_PI;
  for (const Eigen::Vector3f& q : points) {
    if (!q.allFinite()) continue;
    const double r = std::hypot(double(q.x()), double(q.y()));
    if (r >= p.max_radius || r <= 0.0) continue;
    double a = std::atan2(double(q.y()), double(q.x()));
    if (a < 0.0) a += two_pi;
    int ring = static_cast<int>(r / p.max_radius * p.rings);
    int sector = static_cast<int>(a / two_pi * p.sectors);
    if (ring >= p.rings) ring = p.rings - 1;
    if (sector >= p.sectors) sector = p.sectors - 1;
    const float h = static_cast<float>(q.z() + p.height_offset);
    if (h > sc.bins(ring, sector)) sc.bins(ring, sector) = h;
  }
  sc.ring_key.resize(p.rings);
  for (int i = 0; i < p.rings; ++i) {
    int filled = 0;
    for (int j = 0; j < p.sectors; ++j) filled += sc.bins(i, j) > 0.0f ? 1 : 0;
    sc.ring_key(i) = static_cast<float>(filled) / static_cast<float>(p.sectors);
  }
  return sc;
}

ScanContextMatch compareScanContexts(const ScanContext& a, const ScanContext& b) {
  if (a.bins.rows() != b.bins.rows() || a.bins.cols() != b.bins.cols() || a.bins.size() == 0)
    throw std::invalid_argument("scan contexts of different shapes compared");
  const int sectors = static_cast<int>(a.bins.cols());
  Eigen::VectorXf norm_a(sectors), norm_b(sectors);
  for (int j = 0; j < sectors; ++j) {
    norm_a(j) = a.bins.col(j).norm();
    norm_b(j) = b.bins.col(j).norm();
  }
  ScanContextMatch best;
  best.distance = 1.0;
  bool any = false;
  for (int s = 0; s < sectors; ++s) {
    double sum = 0.0;
    int used = 0;
    for (int j = 0; j < sectors; ++j) {
      const int k = (j + s) % sectors;
      if (norm_a(j) <= 0.0f || norm_b(k) <= 0.0f) continue;
      sum += 1.0 - a.bins.col(j).dot(b.bins.col(k)) / (double(norm_a(j)) * norm_b(k));
      ++used;
    }
    if (used == 0) continue;
    const double d = sum / used;
    if (!any || d < best.distance) {
      best.distance = d;
      best.shift = s;
      any = true;
    }
  }
  // Column j of `a` (azimuth α) sees what column j + s of `b` sees (azimuth α + s·Δ): a point at
  // azimuth β in b's frame lies at β - s·Δ in a's frame, so b's frame is a's turned by -s·Δ.
  best.yaw = -2.0 * M_PI * best.shift / sectors;
  return best;
}

}  // namespace metricmap
