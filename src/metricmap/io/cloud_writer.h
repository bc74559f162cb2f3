#pragma once
/// \file cloud_writer.h
/// \brief Write PCD files and text outputs atomically (temporary file, then rename).

#include <string>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

namespace metricmap {

/// \brief PCD body encodings.
enum class PcdFormat { Ascii, Binary, BinaryCompressed };

/// \brief Parse "ascii" | "binary" | "binary_compressed". \throws std::invalid_argument
PcdFormat parsePcdFormat(const std::string& name);

/// \brief Save a cloud as PCD; nothing is left at `path` unless the whole file was written.
/// \throws std::runtime_error naming the file on failure
template <typename PointT>
void savePcdAtomic(const std::string& path, const pcl::PointCloud<PointT>& cloud, PcdFormat format);

/// \brief Write text to `path` through a temporary file and a rename.
/// \throws std::runtime_error naming the file on failure
void writeTextAtomic(const std::string& path, const std::string& text);

}  // namespace metricmap
