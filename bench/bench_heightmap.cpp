// HeightMap binning of one 640x480 Kinect frame (the PCL grabber's, floor found by RANSAC
// once outside the timing), single-threaded.
#include "bench_common.h"
#include "metricmap/camera/camera_intrinsics.h"
#include "metricmap/camera/depth_to_cloud.h"
#include "metricmap/io/depth_image.h"
#include "metricmap/mapping/floor_fit.h"
#include "metricmap/mapping/height_map.h"

namespace metricmap::bench {
namespace {

void BM_HeightMapKinectFrame(benchmark::State& state) {
  const std::string dir = std::string(METRICMAP_DATA_DIR) + "/pcl_grabber_kinect_depth/";
  const DepthImage depth = readDepthImage(dir + "tiff/frame_20121214T142255.814212_depth.tiff");
  const CameraIntrinsics k = readPclGrabberXml(dir + "xml/frame_20121214T142255.814212.xml");
  const auto cloud = depthToCloud(depth, k, k.depth_scale);
  const FloorPlane floor = fitFloor(cloud, 0.02);
  const Eigen::Isometry3d pose = cameraToMapFromFloor(floor.normal, floor.d);
  HeightMapParams p;
  p.resolution = 0.01;
  p.map_size = 400;
  p.z_bins = {0.03, 0.5};
  HeightMap map(p);
  for (auto _ : state) map.addFrame(cloud, pose);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * cloud.size()));
  state.counters["pixels"] = static_cast<double>(cloud.size());
  state.counters["valid_points"] =
      static_cast<double>(map.statistics().valid_points / map.statistics().frames);
}

void BM_DepthToCloudKinectFrame(benchmark::State& state) {
  const std::string dir = std::string(METRICMAP_DATA_DIR) + "/pcl_grabber_kinect_depth/";
  const DepthImage depth = readDepthImage(dir + "tiff/frame_20121214T142255.814212_depth.tiff");
  const CameraIntrinsics k = readPclGrabberXml(dir + "xml/frame_20121214T142255.814212.xml");
  for (auto _ : state) benchmark::DoNotOptimize(depthToCloud(depth, k, k.depth_scale).data());
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * depth.values.size()));
}

BENCHMARK(BM_HeightMapKinectFrame)->Unit(benchmark::kMicrosecond)->MinTime(1.0);
BENCHMARK(BM_DepthToCloudKinectFrame)->Unit(benchmark::kMicrosecond)->MinTime(1.0);

}  // namespace
}  // namespace metricmap::bench
