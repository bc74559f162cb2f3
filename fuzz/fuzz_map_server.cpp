// libFuzzer target for the map and query files of localisation and distance fields: any bytes
// as a map_server YAML (naming a small valid PGM), as the PGM (named by a valid YAML), and as a
// file of point rows (`distance --query`). Each gives its result or an InputError /
// CapacityError.
#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include "fuzz_common.h"
#include "metricmap/common/memory_budget.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/map_server_reader.h"
#include "metricmap/io/point_rows_csv.h"

namespace {

void load(const std::string& yaml) {
  try {
    metricmap::loadMapServer(yaml);
  } catch (const metricmap::InputError&) {
  } catch (const metricmap::CapacityError&) {
  }
}

void readRows(const std::string& path) {
  try {
    const std::vector<double> xyz = metricmap::readPointRows(path);
    if (xyz.empty() || xyz.size() % 3 != 0) __builtin_trap();  // rows come whole
  } catch (const metricmap::InputError&) {
  } catch (const metricmap::CapacityError&) {
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::string pgm = [] {
    metricmap::setMemoryBudget(64u << 20);
    const std::string path = "/tmp/metricmap_fuzz_map_ok.pgm";
    std::ofstream(path, std::ios::binary) << "P5 2 2 255 \x00\xfe\xcd\x80";
    return path;
  }();
  {
    metricmap::fuzz::TempInput yaml(data, size, "map", ".yaml");
    load(yaml.path());
    readRows(yaml.path());
  }
  metricmap::fuzz::TempInput image(data, size, "map", ".pgm");
  const std::string text = "image: " + image.path() +
                           "\nresolution: 0.05\norigin: [0, 0, 0]\nnegate: 0\n"
                           "occupied_thresh: 0.65\nfree_thresh: 0.196\nmode: scale\n";
  const metricmap::fuzz::TempInput yaml(reinterpret_cast<const std::uint8_t*>(text.data()),
                                        text.size(), "map_for_pgm", ".yaml");
  load(yaml.path());
  (void)pgm;
  return 0;
}
