#include "metricmap/distance/distance_volume.h"

namespace metricmap {

VdbVolume vdbVolumeOf(const DistanceField& field) {
  VdbVolume v;
  v.name = "distance";
  v.shape = field.shape();
  if (field.dimensions() == 2) v.shape[2] = 1;
  for (int a = 0; a < 3; ++a) v.origin[a] = field.origin()[a];
  v.resolution = field.resolution();
  v.values = &field.field();
  v.background = static_cast<float>(field.params().max_distance);
  v.level_set = field.params().signed_distance;
  return v;
}

}  // namespace metricmap
