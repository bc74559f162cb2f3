#pragma once
/// \file tum_pose_lines.h
/// \brief A TUM trajectory that must hold no more pose lines than the frames it is given for.

#include <cstddef>
#include <string>

namespace metricmap {

/// \brief A TUM trajectory gives frame k the k-th pose line, so it holds exactly one pose line
/// per frame: readTumTrajectory checked the first `frames`; a line beyond them (extra poses would
/// mean the frames are not the trajectory's first ones, or not in its order) is an error naming
/// the file and that line. Blank lines and '#' comments are not pose lines. The file is scanned
/// in blocks (a line may be as long as the file).
/// \param noun what a frame is, singular ("depth image", "scan"): the message says
/// "the 2 depth image(s) given", "one line per depth image"
/// \throws InputError naming the file (and the first extra pose line)
void requireNoExtraPoses(const std::string& path, std::size_t frames, const std::string& noun);

}  // namespace metricmap
