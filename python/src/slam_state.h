#pragma once
/// \file slam_state.h
/// \brief The Python Slam2D object: a running SLAM, or once finished only its results (the
/// SLAM's working state is freed), which pickle saves and loads.

#include <memory>
#include <vector>

#include "arrays.h"
#include "metricmap/mapping/log_odds_grid_2d.h"
#include "metricmap/slam/slam_2d.h"
#include "object_lock.h"

namespace metricmap::python {

/// \brief What a finished Slam2D gives.
struct Slam2DResult {
  Slam2DConfig config;
  std::vector<Pose2D> trajectory;
  std::vector<std::size_t> node_scans;
  std::vector<LoopClosure2D> loops;
  PoseGraph2D graph;
  Slam2DStats stats;
  std::unique_ptr<LogOddsGrid2D> map;
};

/// \brief metricmap.Slam2D.
struct PySlam {
  std::unique_ptr<Slam2D> slam;          ///< until finished
  std::unique_ptr<Slam2DResult> result;  ///< once finished
  std::vector<double> stamps;            ///< as given to add_scan (NaN: none)
  mutable ObjectMutex mutex;             ///< serialises the object's calls
  bool finished() const { return result != nullptr; }
  /// \brief Keep the results of the finished `slam` and free it.
  void keepResult();
  /// \throws py::value_error before finish()
  const Slam2DResult& finishedResult() const;
};

/// \brief The finished object's state for pickle. \throws py::type_error before finish()
py::tuple slamState(const PySlam& p);
/// \brief A finished object from slamState. \throws py::value_error for another tuple
std::unique_ptr<PySlam> slamFromState(const py::tuple& t);

}  // namespace metricmap::python
