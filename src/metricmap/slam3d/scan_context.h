#pragma once
/// \file scan_context.h
/// \brief A bird's-eye polar descriptor of a local map (Scan Context: Kim and Kim, "Scan Context:
/// Egocentric spatial descriptor for place recognition within 3D point cloud map", IROS 2018):
/// rings (range bins) x sectors (azimuth bins), each bin the highest point above the sensor.
/// A yaw of the sensor shifts the sectors, so the distance is taken over every shift: places
/// are recognised whichever way the sensor faces, a revisit in the opposite direction included.
/// The ring key (the share of filled bins per ring) does not change with yaw and ranks the
/// candidates before the full comparison.

#include <cstddef>
#include <vector>

#include <Eigen/Core>

namespace metricmap {

/// \brief Shape of the descriptor.
struct ScanContextParams {
  int rings = 20;              ///< range bins (>= 1)
  int sectors = 60;            ///< azimuth bins (>= 4)
  double max_radius = 40.0;    ///< points farther (horizontally) are ignored (m, > 0)
  double height_offset = 2.0;  ///< added to z before taking the maximum (m): bins below are empty
};

/// \brief \throws std::invalid_argument naming the first bad field
void validateScanContextParams(const ScanContextParams& params);

/// \brief The descriptor of one place.
struct ScanContext {
  Eigen::MatrixXf bins;      ///< rings x sectors, 0 where empty
  Eigen::VectorXf ring_key;  ///< per ring, the share of filled sectors
};

/// \brief The descriptor of `points` (sensor frame, z up), NaN points skipped.
ScanContext makeScanContext(const std::vector<Eigen::Vector3f>& points,
                            const ScanContextParams& params);

/// \brief How alike two descriptors are, over every sector shift.
struct ScanContextMatch {
  double distance = 1.0;  ///< mean cosine distance of the columns at the best shift, in [0, 1]
  int shift = 0;          ///< sectors `b` is shifted by to match `a`
  /// \brief The yaw (rad) of the frame of `b` in the frame of `a` that the shift gives.
  double yaw = 0.0;
};

/// \brief The Scan Context distance: for each shift s, the mean over the sector pairs where
/// both columns are non-empty of 1 - cos(a_j, b_{j+s}); the smallest over s.
/// \throws std::invalid_argument when the shapes differ
ScanContextMatch compareScanContexts(const ScanContext& a, const ScanContext& b);

}  // namespace metricmap
