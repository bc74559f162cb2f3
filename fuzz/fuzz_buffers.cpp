// libFuzzer target for the buffers ranks exchange (MPI peers, or any producer of them): any
// bytes as a GridAccumulator buffer and as a LogOddsMap buffer, read alone and merged into a
// map. Each gives a result or an InputError; a refused merge leaves the map unchanged.
#include <cstdint>
#include <cstdlib>

#include "metricmap/exceptions.h"
#include "metricmap/grid/grid_accumulator.h"
#include "metricmap/occupancy/log_odds_transfer.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const metricmap::GridAccumulator acc =
        metricmap::GridAccumulator::deserialize(data, size, "fuzz grid buffer");
    (void)acc.result();
  } catch (const metricmap::InputError&) {
  } catch (const metricmap::CapacityError&) {
  }
  try {
    const metricmap::LogOddsMap map = metricmap::deserializeLogOdds(data, size, "fuzz buffer");
    (void)map.occupiedVoxels();
  } catch (const metricmap::InputError&) {
  } catch (const metricmap::CapacityError&) {
  }
  metricmap::LogOddsParams params;
  params.resolution = 0.2;
  params.max_range = 30.0;
  metricmap::LogOddsMap map(params);
  map.setLogOdds({1, 2, 3}, 0.5f);
  try {
    metricmap::mergeSerializedLogOdds(map, data, size, "fuzz buffer");
  } catch (const metricmap::InputError&) {
    if (map.knownVoxels() != 1) std::abort();  // a refused buffer changes nothing
  } catch (const metricmap::CapacityError&) {
  }
  return 0;
}
