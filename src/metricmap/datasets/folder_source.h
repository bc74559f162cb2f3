#pragma once
/// \file folder_source.h
/// \brief A folder of scan files (.pcd, .ply, KITTI .bin, .npy; one format) in natural file-name
/// order, or a list file (.txt, one scan path per line, relative to the list's folder), with an
/// optional `times.txt` (one stamp per scan) and an optional reference pose file (`poses.txt`:
/// KITTI 12-number or TUM 8-number rows, one per scan) beside the scans.

#include <memory>
#include <string>
#include <vector>

#include "metricmap/datasets/scan_source.h"

namespace metricmap {

/// \brief "a2" < "a10": digit runs compared as numbers, the rest byte by byte.
bool naturalLess(const std::string& a, const std::string& b);

/// \brief The scan files of a folder source (`path` a folder: its scans in natural order; a
/// .txt list: the paths it names), without reading them.
/// \throws InputError naming the folder or list when it cannot be read
std::vector<std::string> folderScanPaths(const std::string& path);

/// \brief The scans of a folder or list file.
/// \throws InputError naming the path: no scans, mixed formats, a list naming a missing file,
/// a times file with the wrong count or non-increasing stamps, a pose file of the wrong length
std::unique_ptr<ScanSource> openFolderSource(const std::string& path,
                                             const ScanSourceOptions& options);

}  // namespace metricmap
