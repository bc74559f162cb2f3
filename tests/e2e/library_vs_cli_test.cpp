// The library alone does what the command does: ScanMapper builds the KITTI map of frames 0-5
// cell for cell as `metricmap kitti` writes it, with the same JSON figures, and SplitAndMerge
// with its default parameters gives the segments of `metricmap lines` without options.
// usage: library_vs_cli_test METRICMAP DATA_DIR WORK_DIR
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "metricmap/datasets/kitti_sequence.h"
#include "metricmap/io/cloud_reader.h"
#include "metricmap/io/laser_scan.h"
#include "metricmap/lines/split_and_merge.h"
#include "metricmap/sequence/scan_mapper.h"

namespace {

int failures = 0;

void check(bool ok, const std::string& what) {
  if (!ok) {
    std::cerr << "FAIL: " << what << "\n";
    ++failures;
  }
}

std::string run(const std::string& command) {
  std::string out;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return out;
  char buf[4096];
  for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, pipe)) > 0;) out.append(buf, n);
  if (pclose(pipe) != 0) {
    std::cerr << "FAIL: command failed: " << command << "\n";
    ++failures;
  }
  return out;
}

/// The next header token of a PNM file, skipping '#' comments.
std::string pnmToken(std::istream& in) {
  std::string t;
  while (in >> t && t[0] == '#') {
    std::string rest;
    std::getline(in, rest);
  }
  return t;
}

/// A binary PGM (P5, maxval 255): width, height, pixels.
bool readPgm(const std::string& path, int& w, int& h, std::vector<unsigned char>& pixels) {
  std::ifstream in(path, std::ios::binary);
  const std::string magic = pnmToken(in);
  w = std::atoi(pnmToken(in).c_str());
  h = std::atoi(pnmToken(in).c_str());
  const std::string maxval = pnmToken(in);
  if (magic != "P5" || maxval != "255" || w <= 0 || h <= 0) return false;
  in.get();
  pixels.resize(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
  return static_cast<bool>(
      in.read(reinterpret_cast<char*>(pixels.data()), static_cast<std::streamsize>(pixels.size())));
}

void kittiMap(const std::string& mm, const std::string& data, const std::string& work) {
  const std::string root = data + "/kitti_odometry_00";
  const std::string pgm = work + "/library_vs_cli_map.pgm";
  const nlohmann::json cli = nlohmann::json::parse(
      run("'" + mm + "' kitti '" + root + "' --frames 0-5 --min-range 2.5 --max-height 2.5 " +
          "--min-hits 2 --map-resolution 0.2 --format json --out-map '" + pgm + "'"));

  metricmap::ScanMapperConfig config;  // the same options, as a library user writes them
  config.min_range = 2.5;
  config.max_height = 2.5;
  config.min_hits = 2;
  config.map_resolution = 0.2;
  metricmap::ScanMapper mapper(config);
  const metricmap::KittiSequence seq{root, "00"};
  const Eigen::Isometry3d tr = metricmap::readKittiCalibTr(seq.calib());
  const auto poses = metricmap::readKittiPoses(seq.poses(), 6);
  std::uint64_t read = 0, kept = 0, mapped = 0;
  for (std::size_t i = 0; i < 6; ++i) {
    pcl::PointCloud<pcl::PointXYZ> scan;
    metricmap::loadCloud(seq.scan(i), scan);
    const metricmap::FrameReport r = mapper.addScan(
        scan, metricmap::kittiScanToWorld(poses[i], tr, metricmap::KittiWorld::Camera));
    read += r.points_read;
    kept += r.points_kept;
    mapped += r.points_mapped;
  }
  const metricmap::MapImage image = mapper.map().image();
  check(cli["points_read"] == read, "points_read");
  check(cli["points_kept"] == kept, "points_kept");
  check(cli["points_mapped"] == mapped, "points_mapped");
  check(cli["map"]["width"] == image.width, "map width");
  check(cli["map"]["height"] == image.height, "map height");
  check(cli["map"]["origin"][0] == image.origin_x && cli["map"]["origin"][1] == image.origin_y,
        "map origin");
  check(cli["map"]["cells_with_hits"] == mapper.map().cells(), "cells_with_hits");
  check(cli["map"]["occupied_cells"] == mapper.occupiedCells(), "occupied_cells");
  check(mapper.occupiedCells() > 1000, "a real map: over 1000 occupied cells");

  int w = 0, h = 0;
  std::vector<unsigned char> pixels;
  check(readPgm(pgm, w, h, pixels), "the command's PGM reads back");
  check(w == image.width && h == image.height, "PGM size");
  std::size_t differ = 0;
  for (std::size_t i = 0; i < pixels.size() && i < image.hits.size(); ++i) {
    const unsigned char expected = image.hits[i] >= 2 ? 0 : 254;
    differ += pixels[i] != expected ? 1 : 0;
  }
  check(differ == 0, "every PGM cell equals ScanMapper's (" + std::to_string(differ) + " differ)");
}

void linesDefaults(const std::string& mm, const std::string& data) {
  const std::string log = data + "/breezyslam_mines_urg04lx/exp2.dat";
  for (int scan : {0, 100, 400}) {
    const nlohmann::json cli = nlohmann::json::parse(run("'" + mm + "' lines '" + log +
                                                         "' --preset urg04lx-mines --scan " +
                                                         std::to_string(scan) + " --format json"));
    const metricmap::ScanLog parsed =
        metricmap::readScanLines(log, metricmap::urg04lxMinesFormat());
    metricmap::SplitAndMerge<pcl::PointXYZ> sam;  // default parameters
    sam.setInputCloud(std::make_shared<pcl::PointCloud<pcl::PointXYZ>>(
        metricmap::scanToCloud(parsed.scans[static_cast<std::size_t>(scan)])));
    std::vector<metricmap::LineSegment> segs;
    std::vector<pcl::PointIndices> members;
    sam.segment(segs, members);
    const auto& cli_segs = cli["scans"][0]["segments"];
    check(cli_segs.size() == segs.size(), "scan " + std::to_string(scan) + ": " +
                                              std::to_string(cli_segs.size()) + " vs " +
                                              std::to_string(segs.size()) + " segments");
    for (std::size_t i = 0; i < segs.size() && i < cli_segs.size(); ++i) {
      check(cli_segs[i]["first_index"] == segs[i].first_index &&
                cli_segs[i]["last_index"] == segs[i].last_index,
            "scan " + std::to_string(scan) + " segment " + std::to_string(i));
    }
    check(!segs.empty(), "scan " + std::to_string(scan) + " has segments");
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4) {
    std::cerr << "usage: library_vs_cli_test METRICMAP DATA_DIR WORK_DIR\n";
    return 2;
  }
  kittiMap(argv[1], argv[2], argv[3]);
  linesDefaults(argv[1], argv[2]);
  if (failures == 0) std::cout << "library_vs_cli_test: all checks passed\n";
  return failures == 0 ? 0 : 1;
}
