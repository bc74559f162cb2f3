// Point rows (`distance --query` files): the numbers read as a plain parser written here reads
// them, and every malformed row refused with the file and line.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "metricmap/io/point_rows_csv.h"
#include "scratch_files.h"

namespace {

using metricmap::readPointRows;
using metricmap::test_support::inputErrorOf;
using metricmap::test_support::ScratchDir;

TEST(PointRows, HeaderCommentsBlanksAndTwoOrThreeColumns) {
  const ScratchDir dir("metricmap_point_rows_");
  const std::string p =
      dir.write("q.csv", "x,y,z\n# a comment\n1,2,3\n\n-4.5 5e-1\t6\r\n.25,-1e3\n+7,8,9\n");
  const std::vector<double> want = {1, 2, 3, -4.5, 0.5, 6, 0.25, -1000, 0, 7, 8, 9};
  EXPECT_EQ(readPointRows(p), want);
}

TEST(PointRows, OnlyTheFirstLineMayBeAHeaderAndBadRowsNameTheirLine) {
  const ScratchDir dir("metricmap_point_rows_bad_");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"x,y\ninf,0\n", "b.csv:2: 'inf' is not a finite number"},
      {"x,y\nabc,1\n", "b.csv:2: 'abc' is not a finite number"},
      {"1,2\nx,y\n", "b.csv:2: 'x' is not a finite number"},
      {"1,2\nnan,1\n", "b.csv:2: 'nan' is not a finite number"},
      {"1,2\n1e999,1\n", "b.csv:2:"},
      {"1,2,3,4\n", "b.csv:1: expected x,y or x,y,z, got 4 fields"},
      {"1\n", "b.csv:1: expected x,y or x,y,z, got 1 fields"},
      {"x,y\n", "b.csv: no query point"},
      {"", "b.csv: no query point"},
  };
  for (const auto& [text, needle] : cases) {
    const std::string p = dir.write("b.csv", text);
    const std::string msg = inputErrorOf([&] { readPointRows(p); });
    EXPECT_NE(msg.find(needle), std::string::npos) << text << " -> " << msg;
  }
}

}  // namespace
