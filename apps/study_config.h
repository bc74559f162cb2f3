#pragma once
/// \file study_config.h
/// \brief One configuration of the grid-vs-octree study:
/// "cell_size=S,min_cell_size=M,max_points=N".

#include <cstddef>
#include <string>
#include <vector>

namespace metricmap::cli {

struct StudyConfig {
  float cell_size = 1.0f;
  float min_cell_size = 1.0f;
  std::size_t max_points = 100;
};

/// \brief Parse "cell_size=S,min_cell_size=M,max_points=N" (all three, any order).
/// \return an empty string on success, else what is wrong
std::string parseStudyConfig(const std::string& text, StudyConfig& out);

/// \brief The study's three configurations (1.0/1.0/100, 0.5/0.5/100, 2.0/1.0/200).
std::vector<StudyConfig> studyConfigs();

}  // namespace metricmap::cli
