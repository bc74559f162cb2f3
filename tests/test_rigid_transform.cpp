// One rigid-transform check for every pose from a file or an option, and the KITTI readers
// that use it (poses, calib Tr).
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include "metricmap/common/rigid_transform.h"
#include "metricmap/datasets/kitti_sequence.h"
#include "metricmap/exceptions.h"

#include "temp_dir.h"

namespace metricmap {
namespace {

namespace fs = std::filesystem;

std::string why(const Eigen::Matrix4d& m) {
  try {
    checkRigidTransform(m, "pose");
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "accepted";
}

TEST(RigidTransform, ProperRotationsAndBoundedTranslationsOnly) {
  Eigen::Isometry3d good(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()));
  good.translation() = Eigen::Vector3d(1e5, -3, 0.5);
  EXPECT_EQ(why(good.matrix()), "accepted");
  Eigen::Matrix4d rounded = good.matrix();
  rounded(0, 0) += 5e-7;  // a pose file's 6 printed digits
  EXPECT_EQ(why(rounded), "accepted");

  EXPECT_NE(why(Eigen::Matrix4d::Zero()).find("pose: the 3x3 part is not a rotation"),
            std::string::npos);
  Eigen::Matrix4d reflection = Eigen::Matrix4d::Identity();
  reflection(0, 0) = -1;  // orthonormal, det -1
  EXPECT_NE(why(reflection).find("det -1"), std::string::npos) << why(reflection);
  Eigen::Matrix4d scaled = Eigen::Matrix4d::Identity() * 1.01;
  scaled(3, 3) = 1;
  EXPECT_NE(why(scaled).find("not a rotation"), std::string::npos);
  Eigen::Matrix4d far = Eigen::Matrix4d::Identity();
  far(0, 3) = 1e308;
  EXPECT_NE(why(far).find("translation (1e+308, 0, 0) is beyond 1e+06 m"), std::string::npos)
      << why(far);
  far(0, 3) = 1e6;
  EXPECT_EQ(why(far), "accepted");
  Eigen::Matrix4d nan = Eigen::Matrix4d::Identity();
  nan(1, 1) = std::nan("");
  EXPECT_NE(why(nan).find("not finite"), std::string::npos);
  Eigen::Matrix4d row = Eigen::Matrix4d::Identity();
  row(3, 0) = 1;
  EXPECT_NE(why(row).find("last row"), std::string::npos);
  EXPECT_NO_THROW(checkRigidTransform(row, "3x4 only", /*check_last_row=*/false));
}

std::string kittiError(const std::function<void()>& read) {
  try {
    read();
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(RigidTransform, KittiPosesAndCalibAreChecked) {
  TempDir dir("rigid");
  const std::string id = "1 0 0 0 0 1 0 0 0 0 1 0\n";
  const std::string poses = dir.write("p.txt", id + "1 0 0 1e308 0 1 0 0 0 0 1 0\n");
  EXPECT_NE(kittiError([&] { readKittiPoses(poses, 2); }).find("p.txt: line 2: translation"),
            std::string::npos);
  const std::string zero = dir.write("z.txt", id + "0 0 0 0 0 0 0 0 0 0 0 0\n");
  EXPECT_NE(kittiError([&] { readKittiPoses(zero, 2); }).find("z.txt: line 2: the 3x3 part"),
            std::string::npos);
  const std::string hex = dir.write("h.txt", "0x1 0 0 0 0 1 0 0 0 0 1 0\n");
  EXPECT_NE(kittiError([&] { readKittiPoses(hex, 1); }).find("h.txt: line 1 is not 12 finite"),
            std::string::npos);
  EXPECT_EQ(kittiError([&] { readKittiPoses(dir.write("ok.txt", id + id), 2); }), "accepted");

  const std::string tr = "Tr: 1 0 0 0.1 0 1 0 0 0 0 1 0\n";
  EXPECT_EQ(kittiError([&] { readKittiCalibTr(dir.write("c1.txt", "P0: 1 2 3\n" + tr)); }),
            "accepted");
  EXPECT_NE(kittiError([&] {
              readKittiCalibTr(dir.write("c2.txt", tr + tr));
            }).find("c2.txt: a second 'Tr:' line (line 2)"),
            std::string::npos);
  EXPECT_NE(kittiError([&] {
              readKittiCalibTr(dir.write("c3.txt", "Tr: 0 0 0 0 0 0 0 0 0 0 0 0\n"));
            }).find("c3.txt: Tr (line 1): the 3x3 part is not a rotation"),
            std::string::npos);
}

TEST(RigidTransform, FrameListsRefuseEmptyItems) {
  for (const char* bad : {"0-1,", ",0", "0,,1", "", "1-", "-1"}) {
    EXPECT_THROW(parseFrameList(bad), std::invalid_argument) << bad;
  }
  EXPECT_EQ(parseFrameList("0-2,5"), (std::vector<std::size_t>{0, 1, 2, 5}));
}

}  // namespace
}  // namespace metricmap
