#pragma once
/// \file place_descriptor_3d.h
/// \brief The bird's-eye descriptor (Scan Context) of a place, from a levelled scan or from the
/// map, on one scale: heights above the place's ground, clipped to what a sensor there sees
/// (clip_height + clip_slope × horizontal range), so that a scan and the map at the place where
/// it was taken give alike descriptors.

#include <vector>

#include <Eigen/Core>

#include "metricmap/localization/scan_ground_3d.h"
#include "metricmap/slam3d/scan_context.h"

namespace metricmap {

struct PlaceDescriptorParams {
  ScanContextParams shape;  ///< height_offset: the value of a bin at ground level
  double clip_height = 2.0;
  double clip_slope = 0.2;
};

/// \brief Descriptor of points given relative to the place (x, y horizontal from it, z above
/// its ground): each height clipped, then Scan Context.
ScanContext placeDescriptor(std::vector<Eigen::Vector3f> relative,
                            const PlaceDescriptorParams& params);

/// \brief Descriptor of a scan (sensor frame) levelled by its ground; its sectors are
/// measured from the levelled frame's x axis.
ScanContext scanDescriptor(const std::vector<Eigen::Vector3d>& scan, const ScanGround& ground,
                           const PlaceDescriptorParams& params);

}  // namespace metricmap
