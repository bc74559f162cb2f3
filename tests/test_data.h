#pragma once
// Paths of the bundled data and small helpers shared by the tests.
#include <string>

inline std::string dataPath(const std::string& relative) {
  return std::string(METRICMAP_DATA_DIR) + "/" + relative;
}

inline std::string studyScan(const std::string& name) {
  return dataPath("ua_mapas_metricos_pcd/" + name + ".pcd");
}
