// Runs `metricmap depth-to-cloud` on the PCL grabber's Kinect frames and compares the PCD it
// writes with PCL's own organized PCD of the same frame: same size, same NaN pattern, points
// within 1e-5 m, same colours.
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>

#include <pcl/io/pcd_io.h>
#include <pcl/point_types.h>

int main(int argc, char** argv) {
  if (argc != 4) {
    std::cerr << "usage: depth_cloud_test METRICMAP DATA_DIR TMP_DIR\n";
    return 2;
  }
  const std::string mm = argv[1], data = std::string(argv[2]) + "/pcl_grabber_kinect_depth/";
  int failures = 0;
  for (const char* frame : {"20121214T142255.814212", "20121214T142256.068683"}) {
    const std::string out = std::string(argv[3]) + "/depth_cloud_" + frame + ".pcd";
    const std::string cmd = mm + " depth-to-cloud " + data + "tiff/frame_" + frame +
                            "_depth.tiff --rgb " + data + "tiff/frame_" + frame +
                            "_rgb.tiff --camera " + data + "xml/frame_" + frame + ".xml --out " +
                            out + " > /dev/null";
    if (std::system(cmd.c_str()) != 0) {
      std::cerr << "FAIL: " << cmd << "\n";
      return 1;
    }
    pcl::PointCloud<pcl::PointXYZRGBA> ours, theirs;
    if (pcl::io::loadPCDFile(out, ours) != 0 ||
        pcl::io::loadPCDFile(data + "pcd/frame_" + frame + ".pcd", theirs) != 0) {
      std::cerr << "FAIL: cannot read the clouds\n";
      return 1;
    }
    if (ours.width != theirs.width || ours.height != theirs.height) {
      std::cerr << "FAIL: size " << ours.width << "x" << ours.height << "\n";
      return 1;
    }
    std::size_t nan = 0;
    double worst = 0;
    for (std::size_t i = 0; i < ours.size(); ++i) {
      const bool a = std::isfinite(ours[i].z), b = std::isfinite(theirs[i].z);
      if (a != b) {
        ++failures;
        continue;
      }
      if (!a) {
        ++nan;
        continue;
      }
      worst =
          std::max<double>(worst, (ours[i].getVector3fMap() - theirs[i].getVector3fMap()).norm());
      failures += ours[i].r != theirs[i].r || ours[i].g != theirs[i].g || ours[i].b != theirs[i].b;
    }
    std::cout << frame << ": " << nan << " NaN pixels, worst difference " << worst << " m\n";
    if (worst > 1e-5) ++failures;
    std::remove(out.c_str());
  }
  if (failures) std::cerr << failures << " mismatches\n";
  return failures == 0 ? 0 : 1;
}
