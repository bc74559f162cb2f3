// Depth images -> clouds against PCL's own organized clouds of the same Kinect frames, and the
// intrinsics readers against the files' stated values.
#include <cmath>
#include <filesystem>
#include <fstream>

#include <pcl/io/pcd_io.h>

#include <gtest/gtest.h>

#include "metricmap/camera/camera_intrinsics.h"
#include "metricmap/camera/depth_to_cloud.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/depth_image.h"
#include "test_data.h"

namespace metricmap {
namespace {

const char* kFrames[] = {"20121214T142255.814212", "20121214T142256.068683"};

std::string grabber(const std::string& sub, const std::string& frame, const std::string& suffix) {
  return dataPath("pcl_grabber_kinect_depth/" + sub + "/frame_" + frame + suffix);
}

}  // namespace

TEST(DepthToCloud, EqualsPclGrabberCloudsWithTheSameNaNs) {
  for (const char* frame : kFrames) {
    const DepthImage depth = readDepthImage(grabber("tiff", frame, "_depth.tiff"));
    const RgbImage rgb = readRgbImage(grabber("tiff", frame, "_rgb.tiff"));
    const CameraIntrinsics k = readPclGrabberXml(grabber("xml", frame, ".xml"));
    ASSERT_EQ(depth.width, 640);
    ASSERT_EQ(depth.height, 480);
    EXPECT_EQ(depth.kind, "tiff");
    const auto cloud = depthToCloud(depth, k, k.depth_scale, rgb);

    pcl::PointCloud<pcl::PointXYZRGBA> expected;
    ASSERT_EQ(pcl::io::loadPCDFile(grabber("pcd", frame, ".pcd"), expected), 0);
    ASSERT_EQ(cloud.width, expected.width);
    ASSERT_EQ(cloud.height, expected.height);
    std::size_t nan = 0;
    double worst = 0.0;
    for (std::size_t i = 0; i < cloud.size(); ++i) {
      const bool ours_nan = !std::isfinite(cloud[i].z), pcl_nan = !std::isfinite(expected[i].z);
      ASSERT_EQ(ours_nan, pcl_nan) << "pixel " << i;
      if (ours_nan) {
        ++nan;
        continue;
      }
      worst = std::max<double>(worst,
                               (cloud[i].getVector3fMap() - expected[i].getVector3fMap()).norm());
      ASSERT_EQ(cloud[i].r, expected[i].r) << "pixel " << i;
      ASSERT_EQ(cloud[i].b, expected[i].b) << "pixel " << i;
    }
    EXPECT_LT(worst, 1e-5) << frame;
    EXPECT_GT(nan, 30000u);
    EXPECT_FALSE(cloud.is_dense);
  }
}

TEST(DepthToCloud, TumPngAndOpen3dJson) {
  const DepthImage depth = readDepthImage(dataPath("open3d_tum_depth/TUM_depth.png"));
  const CameraIntrinsics k = readOpen3dJson(dataPath("open3d_tum_depth/camera_primesense.json"));
  EXPECT_EQ(depth.kind, "png");
  EXPECT_DOUBLE_EQ(k.fx, 525.0);
  EXPECT_DOUBLE_EQ(k.fy, 525.0);
  EXPECT_DOUBLE_EQ(k.cx, 319.5);  // column-major: element 6
  EXPECT_DOUBLE_EQ(k.cy, 239.5);
  EXPECT_EQ(k.width, 640);
  const auto cloud = depthToCloud(depth, k, 1.0 / 5000);
  std::size_t valid = 0;
  double zmin = 1e9, zmax = 0;
  for (const auto& p : cloud) {
    if (!std::isfinite(p.z)) continue;
    ++valid;
    zmin = std::min<double>(zmin, p.z);
    zmax = std::max<double>(zmax, p.z);
  }
  // SOURCE.md: 19.2 % missing, valid 7320..46655 -> 1.46..9.33 m.
  EXPECT_NEAR(static_cast<double>(valid) / cloud.size(), 0.808, 0.002);
  EXPECT_NEAR(zmin, 7320 / 5000.0, 1e-6);
  EXPECT_NEAR(zmax, 46655 / 5000.0, 1e-5);
  // Row 0 is the top of the picture: pixel (u, v) back-projects with y = (v - cy) z / fy.
  const std::uint16_t d = depth.at(100, 50);
  if (d != 0) {
    EXPECT_NEAR(cloud.at(100, 50).y, (50 - 239.5) * d / 5000.0 / 525.0, 1e-5);
  }
}

TEST(DepthToCloud, PngRowsInFileOrder) {
  // Pixel values read by a separate from-scratch PNG decoder (zlib + filters, in Python) from
  // TUM_depth.png: file row 100 and row 379 at column 300. Row 0 must be the file's first row.
  const DepthImage depth = readDepthImage(dataPath("open3d_tum_depth/TUM_depth.png"));
  EXPECT_EQ(depth.at(300, 100), 12075);
  EXPECT_EQ(depth.at(300, 379), 12425);
}

TEST(DepthToCloud, IntrinsicsSources) {
  const CameraIntrinsics k = parseIntrinsics("525,526,320.5,240");
  EXPECT_DOUBLE_EQ(k.fy, 526);
  EXPECT_DOUBLE_EQ(k.cx, 320.5);
  EXPECT_THROW(parseIntrinsics("525,526,320"), std::invalid_argument);
  EXPECT_THROW(parseIntrinsics("0,526,320,240"), std::invalid_argument);
  EXPECT_THROW(parseIntrinsics("a,b,c,d"), std::invalid_argument);
  const CameraIntrinsics h = intrinsicsFromHfov(90.0, 640, 480);
  EXPECT_NEAR(h.fx, 320.0, 1e-9);  // (W/2) / tan(45 deg)
  EXPECT_DOUBLE_EQ(h.cx, 320.0);
  EXPECT_THROW(intrinsicsFromHfov(0.0, 640, 480), std::invalid_argument);
  const CameraIntrinsics x = readCameraFile(grabber("xml", kFrames[0], ".xml"));
  EXPECT_DOUBLE_EQ(x.depth_scale, 0.001);
  EXPECT_DOUBLE_EQ(x.cx, 320.0);
}

TEST(DepthToCloud, BadInputs) {
  // Colour image given as depth, 16-bit depth given as colour, a non-image, bad scale.
  EXPECT_THROW(readDepthImage(grabber("tiff", kFrames[0], "_rgb.tiff")), InputError);
  EXPECT_THROW(readDepthImage(dataPath("open3d_tum_depth/TUM_color.png")), InputError);
  EXPECT_THROW(readRgbImage(dataPath("open3d_tum_depth/TUM_depth.png")), InputError);
  EXPECT_THROW(readDepthImage(dataPath("open3d_tum_depth/camera_primesense.json")), InputError);
  const std::string fake = (std::filesystem::temp_directory_path() / "metricmap_fake.png").string();
  std::ofstream(fake) << "not a png";
  EXPECT_THROW(readDepthImage(fake), InputError);
  std::filesystem::remove(fake);
  EXPECT_THROW(readDepthImage("/no/such/depth.png"), InputError);
  EXPECT_THROW(readCameraFile(dataPath("open3d_tum_depth/TUM_depth.png")), InputError);
  const DepthImage depth = readDepthImage(dataPath("open3d_tum_depth/TUM_depth.png"));
  const CameraIntrinsics k = parseIntrinsics("525,525,319.5,239.5");
  EXPECT_THROW(depthToCloud(depth, k, 0.0), std::invalid_argument);
  EXPECT_THROW(depthToCloud(depth, k, -1.0), std::invalid_argument);
  EXPECT_THROW(depthToCloud(depth, k, std::nan("")), std::invalid_argument);
  RgbImage small;
  small.width = 2;
  small.height = 2;
  small.rgb.assign(12, 0);
  EXPECT_THROW(depthToCloud(depth, k, 0.0002, small), std::invalid_argument);
}

}  // namespace metricmap
