#pragma once
/// \file distance_volume.h
/// \brief A distance field as a volume for the VDB writer: its values, box and resolution, the
/// clamp as background (voxels at the max stay inactive), a signed field as a level set.

#include "metricmap/distance/distance_field.h"
#include "metricmap/io/vdb_writer.h"

namespace metricmap {

/// \brief The volume of `field` (a 2D field as one layer of voxels at z = origin z). It refers
/// to the field's values: the field must outlive it and not be updated meanwhile.
VdbVolume vdbVolumeOf(const DistanceField& field);

}  // namespace metricmap
