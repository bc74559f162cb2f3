// Atomic PCD writes: every encoding reads back identically; failures leave nothing behind.
#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "metricmap/io/cloud_reader.h"
#include "metricmap/io/cloud_writer.h"
#include "test_data.h"

namespace metricmap {

namespace fs = std::filesystem;

TEST(CloudWriter, EveryEncodingRoundTrips) {
  pcl::PointCloud<pcl::PointXYZ> cloud;
  loadCloud(dataPath("pcl_test_pcd/car6.pcd"), cloud);
  const fs::path dir =
      fs::temp_directory_path() / ("metricmap_writer_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  for (const char* name : {"ascii", "binary", "binary_compressed"}) {
    const std::string path = (dir / (std::string(name) + ".pcd")).string();
    savePcdAtomic(path, cloud, parsePcdFormat(name));
    pcl::PointCloud<pcl::PointXYZ> back;
    loadCloud(path, back);
    ASSERT_EQ(back.size(), cloud.size()) << name;
    for (std::size_t i = 0; i < back.size(); ++i) {
      ASSERT_NEAR((back[i].getVector3fMap() - cloud[i].getVector3fMap()).norm(), 0.0f, 1e-5f);
    }
  }
  std::size_t files = 0;
  for (const auto& e : fs::directory_iterator(dir)) {
    EXPECT_EQ(e.path().string().find(".tmp-"), std::string::npos) << e.path();
    ++files;
  }
  EXPECT_EQ(files, 3u);
  fs::remove_all(dir);
}

TEST(CloudWriter, FailureLeavesNothing) {
  pcl::PointCloud<pcl::PointXYZ> cloud;
  cloud.push_back(pcl::PointXYZ(1, 2, 3));
  EXPECT_THROW(savePcdAtomic("/nonexistent-dir/x.pcd", cloud, PcdFormat::Binary),
               std::runtime_error);
  EXPECT_THROW(writeTextAtomic("/nonexistent-dir/x.csv", "a"), std::runtime_error);
  // A destination that is a directory: the temporary is written beside it, the final rename
  // fails, and the directory must hold exactly what it held before.
  const fs::path dir =
      fs::temp_directory_path() / ("metricmap_writer_fail_" + std::to_string(::getpid()));
  fs::create_directories(dir / "taken.pcd");
  fs::create_directories(dir / "taken.csv");
  EXPECT_THROW(savePcdAtomic((dir / "taken.pcd").string(), cloud, PcdFormat::Binary),
               std::runtime_error);
  EXPECT_THROW(writeTextAtomic((dir / "taken.csv").string(), "a"), std::runtime_error);
  std::vector<std::string> left;
  for (const auto& e : fs::directory_iterator(dir)) left.push_back(e.path().filename().string());
  std::sort(left.begin(), left.end());
  EXPECT_EQ(left, (std::vector<std::string>{"taken.csv", "taken.pcd"}));
  EXPECT_TRUE(fs::is_directory(dir / "taken.pcd"));
  EXPECT_TRUE(fs::is_empty(dir / "taken.pcd"));
  fs::remove_all(dir);
  EXPECT_THROW(parsePcdFormat("binary-compressed"), std::invalid_argument);
}

}  // namespace metricmap
