// metricmap.read_trajectory / write_trajectory / evaluate_trajectory / read_relations /
// relation_error: trajectory files and metrics (io/trajectory.h, evaluation/).
#include <cmath>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "arrays.h"
#include "metricmap/evaluation/relation_error.h"
#include "metricmap/evaluation/trajectory_evaluation.h"
#include "metricmap/evaluation/trajectory_order.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/cloud_writer.h"
#include "metricmap/io/trajectory.h"
#include "metricmap/io/trajectory_relations.h"
#include "poses.h"
#include "sequence.h"

namespace metricmap::python {

namespace {

/// `name` names the poses argument; the stamps argument is `stamps_name` (default name_stamps).
Trajectory trajectoryFrom(const py::handle& poses, const py::object& stamps, const char* name,
                          const char* stamps_name = nullptr) {
  Trajectory t;
  t.poses = spatialOrPlanarPosesFrom(poses, name);
  if (!stamps.is_none())
    t.stamps = stampsFrom(
        stamps, stamps_name ? stamps_name : (std::string(name) + "_stamps").c_str(), t.size());
  return t;
}

py::dict meanStd(const MeanAndStd& m) {
  py::dict d;
  d["mean"] = m.mean;
  d["std"] = m.stddev;
  return d;
}

std::vector<long long> asLong(const std::vector<std::size_t>& v) {
  return std::vector<long long>(v.begin(), v.end());
}

bool increasing(const std::vector<double>& stamps) {
  for (std::size_t i = 1; i < stamps.size(); ++i)
    if (!(stamps[i] > stamps[i - 1])) return false;
  return true;
}

/// A trajectory with stamps in stamp order; `order` (when not null) receives the given index of
/// each sorted pose (the identity when already in order). Equal stamps: ValueError naming `name`.
Trajectory sortedByStamp(const Trajectory& t, const char* name,
                         std::vector<std::size_t>* order = nullptr) {
  std::vector<std::size_t> o(t.size());
  for (std::size_t i = 0; i < o.size(); ++i) o[i] = i;
  Trajectory sorted = t;
  if (t.hasStamps() && !increasing(t.stamps)) {
    try {
      o = stampOrder(t);
    } catch (const std::invalid_argument& e) {
      throw py::value_error(std::string(name) + ": " + e.what());
    }
    for (std::size_t k = 0; k < o.size(); ++k) {
      sorted.poses[k] = t.poses[o[k]];
      sorted.stamps[k] = t.stamps[o[k]];
    }
  }
  if (order) *order = std::move(o);
  return sorted;
}

/// NaN where a figure is undefined (no segment, no pair), as numpy's mean of nothing.
double definedOr(double value, bool defined) {
  return defined ? value : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

void initEvaluation(py::module_& m) {
  m.def(
      "read_trajectory",
      [](const std::filesystem::path& path, const std::string& format) {
        Trajectory t;
        TrajectoryFormat detected = TrajectoryFormat::Auto;
        const TrajectoryFormat f = parseTrajectoryFormat(format);
        {
          py::gil_scoped_release release;
          t = readTrajectoryFile(path.string(), f, &detected);
        }
        py::object stamps = py::none();
        if (t.hasStamps()) stamps = doublesArray(t.stamps);
        return py::make_tuple(posesArray(t.poses), stamps);
      },
      py::arg("path"), py::arg("format") = "auto", R"doc(
Read a trajectory file: KITTI rows (12 numbers, the 3x4 [R|t]) or TUM rows (stamp tx ty tz
qx qy qz qw).

Parameters
----------
path : str or os.PathLike
format : {'auto', 'kitti', 'tum'}

Returns
-------
(poses, stamps)
    poses (N, 4, 4) float64 (sensor -> world, m); stamps (N,) float64 seconds, or None for
    KITTI rows.

Raises
------
InputError
    a missing or malformed file (named with its line).
)doc");

  m.def(
      "write_trajectory",
      [](const std::filesystem::path& path, ArrayLike poses, py::object stamps,
         const std::string& format) {
        const Trajectory t =
            sortedByStamp(trajectoryFrom(poses, stamps, "poses", "stamps"), "stamps");
        std::string text;
        if (format == "kitti" && !stamps.is_none())
          throw py::value_error("KITTI rows have no stamps: format='tum' writes them");
        if (format == "kitti") {
          text = formatKittiTrajectory(t);
        } else if (format == "tum") {
          text = formatTumTrajectory(t);
        } else {
          throw py::value_error("format must be 'kitti' or 'tum', got '" + format + "'");
        }
        try {
          py::gil_scoped_release release;
          writeTextAtomic(path.string(), text);
        } catch (const std::runtime_error& e) {
          raiseOSError(e);
        }
      },
      py::arg("path"), py::arg("poses"), py::arg("stamps") = py::none(),
      py::arg("format") = "kitti", R"doc(
Write a trajectory as KITTI rows (no stamps: giving them is a ValueError) or TUM rows
(without stamps: the pose index), through a temporary file and a rename. TUM rows are
written in stamp order (raw logs deliver scans out of order); two poses with one stamp are a
ValueError, and stamps must differ as written (9 decimals), as :func:`read_trajectory`
requires.

Parameters
----------
path : str or os.PathLike
poses : array_like, shape (N, 4, 4) or (N, 3)
    Rigid transforms (m), or planar poses x (m), y (m), theta (rad) (as 3D poses at z = 0).
stamps : array_like, shape (N,), optional
    Seconds, in any order.
format : {'kitti', 'tum'}
)doc");

  m.def(
      "evaluate_trajectory",
      [](ArrayLike estimate, ArrayLike reference, py::object estimate_stamps,
         py::object reference_stamps, const std::string& align,
         std::optional<double> max_time_diff) {
        std::vector<std::size_t> est_order, ref_order;
        const Trajectory est = sortedByStamp(trajectoryFrom(estimate, estimate_stamps, "estimate"),
                                             "estimate_stamps", &est_order);
        const Trajectory ref =
            sortedByStamp(trajectoryFrom(reference, reference_stamps, "reference"),
                          "reference_stamps", &ref_order);
        // Options that pairing by index would ignore are refused.
        if (estimate_stamps.is_none() != reference_stamps.is_none())
          throw py::value_error(std::string(estimate_stamps.is_none() ? "reference" : "estimate") +
                                "_stamps without " +
                                (estimate_stamps.is_none() ? "estimate" : "reference") +
                                "_stamps: give both to pair by stamps, or neither to pair by "
                                "index");
        if (max_time_diff && estimate_stamps.is_none())
          throw py::value_error(
              "max_time_diff applies to pairing by stamps: give estimate_stamps and "
              "reference_stamps");
        EvaluationConfig config;
        if (max_time_diff) {
          if (!(*max_time_diff >= 0.0) || !std::isfinite(*max_time_diff))
            throw py::value_error("max_time_diff must be finite and >= 0");
          config.max_time_diff = *max_time_diff;
        }
        config.alignment = parseAlignmentMode(align);
        TrajectoryEvaluation e;
        {
          py::gil_scoped_release release;
          e = evaluateTrajectory(est, ref, config);
        }
        for (std::size_t& i : e.pairs.estimate) i = est_order[i];  // the caller's indices
        for (std::size_t& i : e.pairs.reference) i = ref_order[i];
        py::dict d;
        d["pairs"] =
            py::make_tuple(arrayFrom(asLong(e.pairs.estimate), {py::ssize_t(e.pairs.size())}),
                           arrayFrom(asLong(e.pairs.reference), {py::ssize_t(e.pairs.size())}));
        d["paired_by"] = e.pairs.mode == PairingMode::Stamps ? "stamps" : "index";
        py::dict al;
        al["mode"] = alignmentModeName(e.alignment_mode);
        py::array_t<double> rot({py::ssize_t(3), py::ssize_t(3)});
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) rot.mutable_data()[3 * i + j] = e.alignment.rotation(i, j);
        al["rotation"] = rot;
        al["translation"] = doublesArray({e.alignment.translation.x(), e.alignment.translation.y(),
                                          e.alignment.translation.z()});
        al["scale"] = e.alignment.scale;
        d["alignment"] = al;
        py::dict ate;
        ate["translation"] = doublesArray(e.ate.translation);
        ate["rotation_deg"] = doublesArray(e.ate.rotation_deg);
        ate["translation_stats"] = errorStatsDict(e.ate.translation_stats);
        ate["rotation_stats"] = errorStatsDict(e.ate.rotation_stats);
        d["ate"] = ate;
        py::dict rpe;
        rpe["translation"] = doublesArray(e.rpe.translation);
        rpe["rotation_deg"] = doublesArray(e.rpe.rotation_deg);
        rpe["translation_stats"] = errorStatsDict(e.rpe.translation_stats);
        rpe["rotation_stats"] = errorStatsDict(e.rpe.rotation_stats);
        d["rpe"] = rpe;
        py::dict drift;
        drift["path_length"] = e.drift.path_length;
        drift["segments"] = e.drift.segments;
        drift["translation_percent"] = definedOr(e.drift.translation_percent, e.drift.segments > 0);
        drift["rotation_deg_per_m"] = definedOr(e.drift.rotation_deg_per_m, e.drift.segments > 0);
        py::list lengths;
        for (const KittiDriftLength& l : e.drift.lengths) {
          py::dict x;
          x["length"] = l.length;
          x["segments"] = l.segments;
          x["translation_percent"] = definedOr(l.translation_percent, l.segments > 0);
          x["rotation_deg_per_m"] = definedOr(l.rotation_deg_per_m, l.segments > 0);
          lengths.append(x);
        }
        drift["lengths"] = lengths;
        d["drift"] = drift;
        return d;
      },
      py::arg("estimate"), py::arg("reference"), py::arg("estimate_stamps") = py::none(),
      py::arg("reference_stamps") = py::none(), py::arg("align") = "rigid",
      py::arg("max_time_diff") = py::none(), R"doc(
ATE, per-frame RPE and KITTI drift of an estimate against a reference (`metricmap evaluate
--reference`): pair the poses (by stamps when both have them, else by index), align the
paired positions (Umeyama), then the errors.

Parameters
----------
estimate, reference : array_like, shape (N, 4, 4) and (M, 4, 4), or (N, 3) and (M, 3)
    Sensor -> world poses (m), or planar poses x (m), y (m), theta (rad).
estimate_stamps, reference_stamps : array_like, shape (N,) and (M,), optional
    Seconds, in any order (the poses are paired and their RPE taken in stamp order; `pairs`
    gives the indices of the arrays as given). Two poses with one stamp are a ValueError.
align : {'none', 'rigid', 'sim'}
max_time_diff : float, optional
    Largest stamp difference (s) that pairs two poses (default 0.01); only with both stamps.

Returns
-------
dict
    pairs (estimate indices, reference indices), paired_by, alignment (mode, rotation (3, 3),
    translation (3,), scale), ate and rpe (translation (K,) m, rotation_deg (K,),
    translation_stats and rotation_stats: count, rmse, mean, median, std, min, max; NaN when
    count is 0), drift (path_length m, segments, translation_percent, rotation_deg_per_m,
    lengths; the figures are NaN where there is no segment: a path shorter than 100 m).

Raises
------
ValueError
    bad shapes, non-rigid or non-finite poses, too few pairs, a bad option.
)doc");

  m.def(
      "read_relations",
      [](const std::filesystem::path& path) {
        std::vector<PoseRelation> r;
        {
          py::gil_scoped_release release;
          r = readRelations(path.string());
        }
        py::array_t<double> stamps({py::ssize_t(r.size()), py::ssize_t(2)});
        std::vector<Eigen::Isometry3d> rel;
        for (std::size_t k = 0; k < r.size(); ++k) {
          stamps.mutable_data()[2 * k] = r[k].stamp1;
          stamps.mutable_data()[2 * k + 1] = r[k].stamp2;
          rel.push_back(r[k].relative);
        }
        return py::make_tuple(stamps, posesArray(rel));
      },
      py::arg("path"), R"doc(
Read a relations file of the Freiburg SLAM benchmark (Kümmerle et al. 2009): lines
``t1 t2 x y z roll pitch yaw`` (s, m, rad; rotation Rz(yaw) Ry(pitch) Rx(roll)).

Returns
-------
(stamps, relative)
    stamps (K, 2) float64 seconds; relative (K, 4, 4) float64, the sensor's pose at t2 in its
    frame at t1.

Raises
------
InputError
    a missing or malformed file.
)doc");

  m.def(
      "relation_error",
      [](ArrayLike poses, ArrayLike stamps, py::object relations, py::object relation_stamps,
         double max_time_diff, py::object odometry_poses, py::object odometry_stamps) {
        Trajectory t;
        t.poses = spatialOrPlanarPosesFrom(poses, "poses");
        t.stamps = stampsFrom(stamps, "stamps", t.size());
        Trajectory odo;
        if (odometry_poses.is_none() != odometry_stamps.is_none())
          throw py::value_error("odometry_poses and odometry_stamps go together");
        if (!odometry_poses.is_none()) {
          odo.poses = spatialOrPlanarPosesFrom(odometry_poses, "odometry_poses");
          odo.stamps = stampsFrom(odometry_stamps.cast<ArrayLike>(), "odometry_stamps", odo.size());
          if (odo.empty()) throw py::value_error("odometry_poses is empty");
        }
        if (!(max_time_diff >= 0.0) || !std::isfinite(max_time_diff))
          throw py::value_error("max_time_diff must be finite and >= 0");
        std::vector<PoseRelation> rel;
        if (py::isinstance<py::str>(relations) ||
            py::isinstance(relations, py::module_::import("os").attr("PathLike"))) {
          if (!relation_stamps.is_none())
            throw py::value_error("relation_stamps is for relations given as an array");
          const std::string path = relations.cast<std::filesystem::path>().string();
          py::gil_scoped_release release;
          rel = readRelations(path);
        } else {
          if (relation_stamps.is_none())
            throw py::value_error("relations given as (K, 4, 4) poses need relation_stamps (K, 2)");
          const std::vector<Eigen::Isometry3d> r = posesFrom(relations, "relations");
          auto s = doublesFromArray(relation_stamps, "relation_stamps");
          if (s.ndim() != 2 || s.shape(1) != 2 || static_cast<std::size_t>(s.shape(0)) != r.size())
            throw py::value_error("relation_stamps must have shape (K, 2), one row per relation");
          for (std::size_t k = 0; k < r.size(); ++k) {
            PoseRelation p;
            p.stamp1 = s.data()[2 * k];
            p.stamp2 = s.data()[2 * k + 1];
            if (!std::isfinite(p.stamp1) || !std::isfinite(p.stamp2))
              throw py::value_error("relation_stamps must be finite");
            p.relative = r[k];
            rel.push_back(p);
          }
        }
        RelationError e;
        {
          py::gil_scoped_release release;
          e = relationError(t, rel, max_time_diff, odo.empty() ? nullptr : &odo);
        }
        py::dict d;
        d["used"] = e.used;
        d["stamps_placed_by_odometry"] = e.interpolated;
        d["skipped"] = arrayFrom(asLong(e.skipped), {py::ssize_t(e.skipped.size())});
        d["translation"] = doublesArray(e.translation);
        d["rotation_deg"] = doublesArray(e.rotation_deg);
        d["translation_abs"] = meanStd(e.translation_abs);
        d["translation_sq"] = meanStd(e.translation_sq);
        d["rotation_abs_deg"] = meanStd(e.rotation_abs_deg);
        d["rotation_sq_deg"] = meanStd(e.rotation_sq_deg);
        return d;
      },
      py::arg("poses"), py::arg("stamps"), py::arg("relations"),
      py::arg("relation_stamps") = py::none(), py::arg("max_time_diff") = 0.01,
      py::arg("odometry_poses") = py::none(), py::arg("odometry_stamps") = py::none(), R"doc(
The relation metric of Kümmerle et al. (2009) (`metricmap evaluate --relations`): for each
relation whose two stamps are found in `stamps` (nearest within `max_time_diff`), the error
delta*⁻¹ (P_i⁻¹ P_j). With the log's raw odometry, a stamp without an estimated pose is placed
as the benchmark's tool places it: the nearest estimated pose moved by the odometry's motion
(`--odometry`).

Parameters
----------
poses : array_like, shape (N, 4, 4)
    The estimate (sensor -> world, m).
stamps : array_like, shape (N,)
    Seconds; need not increase.
relations : str or os.PathLike or array_like
    A relations file, or (K, 4, 4) relative poses with `relation_stamps`.
relation_stamps : array_like, shape (K, 2), optional
    (t1, t2) per relation, seconds.
max_time_diff : float
    Seconds.
odometry_poses : array_like, shape (M, 4, 4), optional
    The raw odometry (e.g. a CARMEN log's, from a scan source's scans), with
odometry_stamps : array_like, shape (M,), optional
    its stamps (s; need not increase).

Returns
-------
dict
    used, skipped (indices of relations not found), stamps_placed_by_odometry, translation (used,) m, rotation_deg
    (used,), translation_abs / translation_sq / rotation_abs_deg / rotation_sq_deg as
    {mean, std} (std over n - 1).

Raises
------
ValueError
    bad shapes, non-finite values. InputError: a bad relations file.
)doc");
}

}  // namespace metricmap::python
