#pragma once
/// \file map_server.h
/// \brief ROS map_server maps: a PGM image and the YAML that describes it.

#include <cstdint>
#include <string>
#include <vector>

#include "metricmap/common/map_server_image.h"
#include "metricmap/io/output_set.h"

namespace metricmap {

/// \brief The files of a map_server map: PGM, YAML beside it, and optional PNG preview and
/// heat map; `image_name` is what the YAML's `image:` names (the PGM's final file name).
struct MapServerFiles {
  std::string pgm, yaml, preview_png, heat_png, image_name;
};

/// \brief M.pgm -> M.pgm, M.yaml, M_preview.png, M_heat.png, image "M.pgm" (without a
/// directory).
MapServerFiles mapServerFiles(const std::string& pgm_path);

/// \brief The one map_server writer: the PGM (P5), the YAML (image, [mode,] resolution,
/// origin [x, y, 0], negate 0, occupied_thresh 0.65, free_thresh 0.196), the PNG preview when
/// its path is not empty, and the heat map (RGB, `heat_rgb`: width x height x 3) when both its
/// path and `heat_rgb` are not empty. Each file through a temporary name and a rename.
/// \throws std::invalid_argument for an empty image or a pixel count that is not width x height
void writeMapServer(const MapServerImage& image, const MapServerFiles& files,
                    const std::vector<std::uint8_t>& heat_rgb = {});

/// \brief writeMapServer into `outputs`: the PGM and YAML, the preview when `files.preview_png` is
/// not empty and the heat map when both its path and `heat_rgb` are not, each staged (renamed
/// into place when `outputs` commits).
void writeMapServer(const MapServerImage& image, MapServerFiles files, OutputSet& outputs,
                    const std::vector<std::uint8_t>& heat_rgb = {});

}  // namespace metricmap
