#pragma once
/// \file compare_report.h
/// \brief The study table of `metricmap compare` (table, Markdown, CSV or JSON) and its plot.

#include <cstddef>
#include <string>
#include <vector>

#include "metricmap/octree/grid_octree_study.h"
#include "pcl_peer.h"
#include "study_config.h"

namespace metricmap::cli {

/// \brief One job of the study: a file with one configuration.
struct StudyRecord {
  std::string file;
  std::size_t points = 0;
  StudyConfig config;
  GridOctreeFigures figures;
  double load_s = 0;
  PclOctreeFigures pcl;  ///< with --pcl-octree
};

/// \brief The table of `records` (`format` json, csv, markdown, else aligned); the
/// pcl::octree columns `with_pcl`.
std::string renderStudy(const std::vector<StudyRecord>& records, const std::string& format,
                        bool with_pcl);

/// \brief The figures as grouped bars at `path` (.png or .svg, the drawing module).
void plotStudy(const std::vector<StudyRecord>& records, bool with_pcl, const std::string& path);

}  // namespace metricmap::cli
