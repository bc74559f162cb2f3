#pragma once
/// \file ply_check.h
/// \brief Checks a PLY header's vertex count against the file size before pcl::io reads it.

#include <string>

namespace metricmap {

/// \throws InputError naming the file when the header is missing, unterminated, or announces
/// more vertices than the body can hold
void checkPlyFile(const std::string& path);

}  // namespace metricmap
