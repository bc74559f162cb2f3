#include "metricmap/common/rigid_transform.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include <Eigen/LU>

namespace metricmap {

void checkRigidTransform(const Eigen::Matrix4d& m, const std::string& what, bool check_last_row) {
  auto fail = [&](const std::string& why) { throw std::invalid_argument(what + ": " + why); };
  if (!m.allFinite()) fail("not finite");
  const Eigen::Matrix3d r = m.topLeftCorner<3, 3>();
  const double orthonormal =
      (r.transpose() * r - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  const double det = r.determinant();
  if (!(orthonormal <= kRotationTolerance) || !(std::abs(det - 1.0) <= kRotationTolerance)) {
    std::ostringstream os;
    os.precision(3);
    os << "the 3x3 part is not a rotation (|R^T R - I| up to " << orthonormal << ", det " << det
       << "; tolerance " << kRotationTolerance << ")";
    fail(os.str());
  }
  const Eigen::Vector3d t = m.topRightCorner<3, 1>();
  if (!(t.cwiseAbs().maxCoeff() <= kMaxTranslation)) {
    std::ostringstream os;
    os.precision(6);
    os << "translation (" << t.x() << ", " << t.y() << ", " << t.z() << ") is beyond "
       << kMaxTranslation << " m";
    fail(os.str());
  }
  if (check_last_row && m.row(3) != Eigen::RowVector4d(0, 0, 0, 1)) {
    std::ostringstream os;
    os << "the last row must be 0 0 0 1, got " << m.row(3);
    fail(os.str());
  }
}

}  // namespace metricmap
