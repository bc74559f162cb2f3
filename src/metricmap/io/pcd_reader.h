#pragma once
/// \file pcd_reader.h
/// \brief PCD files through pcl::io's body decoders, with metricmap's own checked header.

#include <string>

#include <pcl/PCLPointCloud2.h>

#include "metricmap/io/load_report.h"

namespace metricmap {

/// \brief Read a PCD file (ascii, binary, binary_compressed) into a blob.
///
/// The header is parsed and checked against the file size here (pcl::PCDReader's own header
/// parser allocates whatever POINTS says and was seen to crash on crafted input); the body is
/// then decoded by pcl::PCDReader::readBodyASCII / readBodyBinary with that layout.
/// \throws InputError naming the file
void readPcd(const std::string& path, pcl::PCLPointCloud2& blob, LoadReport& report);

}  // namespace metricmap
