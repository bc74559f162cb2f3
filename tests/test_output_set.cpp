// OutputSet: outputs appear together or not at all; special files are never replaced.
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "metricmap/io/cloud_writer.h"
#include "metricmap/io/output_set.h"

#include "temp_dir.h"

namespace metricmap {
namespace {

namespace fs = std::filesystem;

std::string slurp(const std::string& p) {
  std::ifstream in(p);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

std::size_t entries(const fs::path& dir) {
  std::size_t n = 0;
  for (auto it = fs::recursive_directory_iterator(dir); it != fs::recursive_directory_iterator();
       ++it)
    ++n;
  return n;
}

}  // namespace

TEST(OutputSet, CommitsEveryOutputTogether) {
  TempDir d("outputs");
  OutputSet set;
  const std::string a = set.stage(d / "a.csv");
  const std::string b = set.stage(d / "b.svg");
  EXPECT_EQ(fs::path(b).extension(), ".svg");  // writers pick the format from the extension
  EXPECT_EQ(fs::path(a).parent_path(), d.path);
  writeTextAtomic(a, "one");
  writeTextAtomic(b, "two");
  EXPECT_FALSE(fs::exists(d / "a.csv"));
  set.commit();
  EXPECT_EQ(slurp(d / "a.csv"), "one");
  EXPECT_EQ(slurp(d / "b.svg"), "two");
  EXPECT_EQ(entries(d.path), 2u);
}

TEST(OutputSet, NothingLeftWhenALaterOutputFails) {
  TempDir d("outputs");
  {
    OutputSet set;
    writeTextAtomic(set.stage(d / "first.png"), "x");
    std::string steps = set.stageDirectory(d / "steps");
    writeTextAtomic(steps + "/s1.svg", "y");
    EXPECT_THROW(set.stage(d / "missing/second.csv"), std::runtime_error);
  }
  EXPECT_EQ(entries(d.path), 0u);
}

TEST(OutputSet, SpecialFilesAndDirectoriesAreNeverReplaced) {
  TempDir d("outputs");
  ASSERT_EQ(::mkfifo((d / "fifo.pcd").c_str(), 0600), 0);
  fs::create_directories(d / "dir.csv");
  OutputSet set;
  EXPECT_THROW(set.stage(d / "fifo.pcd"), std::runtime_error);
  EXPECT_THROW(set.stage(d / "dir.csv"), std::runtime_error);
  EXPECT_THROW(writeTextAtomic(d / "fifo.pcd", "x"), std::runtime_error);
  EXPECT_THROW(checkOutputPath("/dev/null"), std::runtime_error);
  struct stat st {};
  ASSERT_EQ(::stat((d / "fifo.pcd").c_str(), &st), 0);
  EXPECT_TRUE(S_ISFIFO(st.st_mode));
  EXPECT_TRUE(fs::is_directory(d / "dir.csv"));
}

TEST(OutputSet, StepsIntoAnExistingDirectory) {
  TempDir d("outputs");
  fs::create_directories(d / "steps.v2");
  writeTextAtomic(d / "steps.v2/old.txt", "keep");
  OutputSet set;
  const std::string tmp = set.stageDirectory(d / "steps.v2");
  writeTextAtomic(tmp + "/step_0001.svg", "s");
  set.commit();
  EXPECT_EQ(slurp(d / "steps.v2/step_0001.svg"), "s");
  EXPECT_EQ(slurp(d / "steps.v2/old.txt"), "keep");
  EXPECT_EQ(entries(d / "steps.v2"), 2u);
}

TEST(OutputSet, WriteToAFullDiskFails) {
  if (::access("/dev/full", W_OK) != 0) GTEST_SKIP() << "no /dev/full";
  // The stream reports the failure at the final flush: the check must include it.
  std::ofstream out("/dev/full");
  out << std::string(1 << 16, 'x');
  out.close();
  EXPECT_TRUE(out.fail());
}

}  // namespace metricmap
