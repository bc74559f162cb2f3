// metricmap.se2_to_se3 / se3_to_se2: planar poses (x, y, theta) <-> (4, 4) rigid transforms.
#include <string>
#include <vector>

#include "arrays.h"
#include "poses.h"

namespace metricmap::python {

void initPoseConversion(py::module_& m) {
  m.def(
      "se2_to_se3",
      [](ArrayLike poses) -> py::array_t<double> {
        auto a = doublesFromArray(poses, "poses");
        const bool single = a.ndim() == 1;
        if (!((single && a.shape(0) == 3) || (a.ndim() == 2 && a.shape(1) == 3)))
          throw py::value_error("poses must have shape (3,) or (N, 3): x (m), y (m), theta (rad)");
        const std::vector<Pose2D> planar = planarPosesFrom(poses, "poses", true);
        std::vector<Eigen::Isometry3d> out;
        out.reserve(planar.size());
        for (const Pose2D& p : planar) out.push_back(spatial(p));
        py::array_t<double> result = posesArray(out);
        if (single) return result.reshape({4, 4});
        return result;
      },
      py::arg("poses"), R"doc(
Planar poses as 3D rigid transforms: z = 0, rotation theta about z.

Parameters
----------
poses : array_like, shape (N, 3) or (3,)
    x (m), y (m), theta (rad), as ``Slam2D.trajectory`` gives them; finite.

Returns
-------
ndarray, shape (N, 4, 4) or (4, 4), float64
    What :func:`write_trajectory` and :func:`evaluate_trajectory` take (they take (N, 3) too).
)doc");

  m.def(
      "se3_to_se2",
      [](ArrayLike poses) -> py::array_t<double> {
        auto a = doublesFromArray(poses, "poses");
        const bool single = a.ndim() == 2;
        py::object stacked = single ? py::object(a.reshape({1, 4, 4})) : py::object(a);
        const std::vector<Eigen::Isometry3d> spatial3 = posesFrom(stacked, "poses", true);
        std::vector<Pose2D> out;
        out.reserve(spatial3.size());
        for (const Eigen::Isometry3d& t : spatial3) out.push_back(planar(t));
        py::array_t<double> result = poses2dArray(out);
        if (single) return result.reshape({3});
        return result;
      },
      py::arg("poses"), R"doc(
The planar part of 3D poses: x, y and the yaw atan2(R[1, 0], R[0, 0]) (z, roll and pitch are
dropped).

Parameters
----------
poses : array_like, shape (N, 4, 4) or (4, 4)
    Rigid transforms (m).

Returns
-------
ndarray, shape (N, 3) or (3,), float64
    x (m), y (m), theta (rad) in (-pi, pi].
)doc");
}

}  // namespace metricmap::python
