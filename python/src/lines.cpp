// metricmap.split_and_merge: Split & Merge on one 2D scan (lines/split_and_merge.h), and the
// scan-log readers (io/laser_scan.h).
#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "arrays.h"
#include "metricmap/common/float_range.h"
#include "metricmap/common/format_number.h"
#include "metricmap/io/laser_scan.h"
#include "metricmap/lines/split_and_merge.h"

namespace metricmap::python {

namespace {

PurgeOrder parsePurge(const std::string& s) {
  if (s == "before-merge") return PurgeOrder::BeforeMerge;
  if (s == "after-merge") return PurgeOrder::AfterMerge;
  throw py::value_error("purge must be 'before-merge' or 'after-merge', got '" + s + "'");
}

}  // namespace

void initLines(py::module_& m) {
  m.def(
      "read_scan_log",
      [](const std::filesystem::path& path, std::optional<std::string> preset) {
        std::optional<ScanLineFormat> format;
        if (preset) {
          if (*preset != "urg04lx-mines")
            throw py::value_error("preset must be 'urg04lx-mines' or None, got '" + *preset + "'");
          format = urg04lxMinesFormat();
        }
        ScanLog log;
        {
          py::gil_scoped_release release;
          log = readScanLog(path.string(), format ? &*format : nullptr);
        }
        // What the command prints about skipped lines, as Python warnings.
        for (const std::string& w : log.warnings)
          if (PyErr_WarnEx(PyExc_UserWarning, w.c_str(), 1) != 0) throw py::error_already_set();
        py::list scans;
        for (const LaserScan& s : log.scans) {
          const py::ssize_t n = static_cast<py::ssize_t>(s.ranges.size());
          py::array_t<double> a(n), r(n);
          std::copy(s.angles.begin(), s.angles.end(), a.mutable_data());
          std::copy(s.ranges.begin(), s.ranges.end(), r.mutable_data());
          scans.append(py::make_tuple(a, r));
        }
        return scans;
      },
      py::arg("path"), py::arg("preset") = py::none(), R"doc(
Read the scans of a 2D laser log: CSV "angle,range", CARMEN (FLASER / ROBOTLASER1; plain,
.gz, .bz2), or one scan per line with `preset='urg04lx-mines'` (BreezySLAM's exp*.dat).

Lines that cannot be a scan are skipped with a UserWarning each (what `metricmap lines`
prints).

Returns
-------
list of (angles, ranges)
    Per scan two (B,) float64 arrays: radians (counter-clockwise, x forward) and metres
    (NaN for an invalid beam).

Raises
------
InputError (an OSError)
    unreadable file, undetectable layout, no scan.
)doc");

  m.def(
      "split_and_merge",
      [](ArrayLike angles, ArrayLike ranges, double distance_threshold, double angle_threshold,
         std::int64_t min_points, double min_length, double max_gap,
         std::optional<std::string> purge, std::optional<double> chi2, double range_sigma,
         double bearing_sigma) {
        if (min_points < 0) throw py::value_error("min_points must be >= 0");
        // A piece holds at least one point: min_points 1 purges no more than 0.
        if (purge && !(min_points > 1 || min_length > 0.0))
          throw py::value_error("purge has no effect with min_points " +
                                std::to_string(min_points) +
                                " and min_length 0: nothing is purged (every segment has a point)");
        if (purge && !(angle_threshold > 0.0))
          throw py::value_error(
              "purge has no effect with angle_threshold 0: there is no merge step to purge "
              "before or after");
        SplitAndMergeParams params;
        params.distance_threshold = distance_threshold;
        params.angle_threshold = angle_threshold;
        params.min_points = static_cast<std::size_t>(min_points);
        params.min_length = min_length;
        params.max_gap = max_gap;
        params.purge_order = parsePurge(purge.value_or("before-merge"));
        params.chi2_split = chi2.has_value();
        if (chi2) params.chi2_threshold = *chi2;
        params.range_sigma = range_sigma;
        params.bearing_sigma = bearing_sigma;
        auto r = doublesFromArray(ranges, "ranges");
        auto a = doublesFromArray(angles, "angles");
        if (r.ndim() != 1 || a.ndim() != 1 || r.shape(0) != a.shape(0))
          throw py::value_error("ranges and angles must be 1-D arrays of the same length");
        LaserScan scan;
        scan.ranges.assign(r.data(), r.data() + r.size());
        scan.angles.assign(a.data(), a.data() + a.size());
        validateLaserScan(scan);
        for (std::size_t k = 0; k < scan.ranges.size(); ++k)
          if (beyondFloatRange(scan.ranges[k]))  // would become inf: a beam without a return
            throw py::value_error("beam " + std::to_string(k) + ": range " +
                                  formatNumber(scan.ranges[k]) +
                                  " is beyond the single-precision range");
        // An invalid beam (NaN, <= 0) gives no point.
        for (double& range : scan.ranges)
          if (!(range > 0.0)) range = std::nan("");
        std::vector<LineSegment> segments;
        std::vector<pcl::PointIndices> members;
        {
          py::gil_scoped_release release;
          auto cloud = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>(scanToCloud(scan));
          SplitAndMerge<pcl::PointXYZ> sam;
          sam.setParams(params);
          sam.setInputCloud(cloud);
          sam.segment(segments, members);
        }
        const py::ssize_t n = static_cast<py::ssize_t>(segments.size());
        py::array_t<double> start({n, py::ssize_t(2)}), end({n, py::ssize_t(2)});
        py::array_t<std::int64_t> first({n}), last({n}), points({n});
        py::array_t<double> rr({n}), alpha({n}), cov({n, py::ssize_t(2), py::ssize_t(2)});
        py::list member_list;
        for (py::ssize_t i = 0; i < n; ++i) {
          const LineSegment& s = segments[static_cast<std::size_t>(i)];
          start.mutable_at(i, 0) = s.start.x();
          start.mutable_at(i, 1) = s.start.y();
          end.mutable_at(i, 0) = s.end.x();
          end.mutable_at(i, 1) = s.end.y();
          first.mutable_at(i) = s.first_index;
          last.mutable_at(i) = s.last_index;
          points.mutable_at(i) = static_cast<std::int64_t>(s.points);
          rr.mutable_at(i) = s.fit.r;
          alpha.mutable_at(i) = s.fit.alpha;
          for (int u = 0; u < 2; ++u)
            for (int v = 0; v < 2; ++v) cov.mutable_at(i, u, v) = s.fit.cov(u, v);
          const auto& idx = members[static_cast<std::size_t>(i)].indices;
          py::array_t<std::int64_t> mem(static_cast<py::ssize_t>(idx.size()));
          std::copy(idx.begin(), idx.end(), mem.mutable_data());
          member_list.append(mem);
        }
        py::dict d;
        d["start"] = start;
        d["end"] = end;
        d["first_index"] = first;
        d["last_index"] = last;
        d["points"] = points;
        d["r"] = rr;
        d["alpha"] = alpha;
        d["cov"] = cov;
        d["members"] = member_list;
        return d;
      },
      py::arg("angles"), py::arg("ranges"), py::kw_only(), py::arg("distance_threshold") = 0.05,
      py::arg("angle_threshold") = 5.0 * 3.14159265358979323846 / 180.0, py::arg("min_points") = 5,
      py::arg("min_length") = 0.1, py::arg("max_gap") = 0.0, py::arg("purge") = py::none(),
      py::arg("chi2") = py::none(), py::arg("range_sigma") = 0.01,
      py::arg("bearing_sigma") = 0.1 * 3.14159265358979323846 / 180.0, R"doc(
Split & Merge line segments of one ordered 2D scan (the `metricmap lines` algorithm):
``split_and_merge(*scan.laser)``; every option is keyword-only.

Parameters
----------
angles, ranges : array_like, shape (B,)
    Radians (finite, within [-2 pi, 2 pi]) and metres, beam order: the order ``Scan.laser``
    and :func:`read_scan_log` give. A range that is NaN or <= 0 is an invalid beam; a finite
    range beyond the float32 range (3.4e38) is a ValueError.
distance_threshold : float
    Split where the farthest point is further than this from the chord, metres (> 0).
angle_threshold : float
    Merge neighbours whose directions differ less, radians (0: off).
min_points, min_length : int, float
    Purge segments with fewer points / shorter (0: off).
max_gap : float
    Split where consecutive valid points are further apart, metres (0: off).
purge : {'before-merge', 'after-merge'}, optional
    When purge runs (default before-merge); giving it where nothing is purged (min_points <= 1
    and min_length 0) or nothing is merged (angle_threshold 0) is a ValueError.
chi2 : float, optional
    Split on the chi-square test d^2 / var(d) > chi2 instead (e.g. 6.63).
range_sigma, bearing_sigma : float
    Point noise (metres, radians) for the fits' covariances and the chi-square test.

Returns
-------
dict of arrays, S segments in scan order
    start, end (S, 2) float64; first_index, last_index, points (S,) int64 (beam indices,
    point counts); r, alpha (S,) float64 (line x cos(alpha) + y sin(alpha) = r);
    cov (S, 2, 2) covariance of (r, alpha); members: list of S int64 arrays of beam indices.
)doc");
}

}  // namespace metricmap::python
