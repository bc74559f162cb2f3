#include "stats_json.h"

namespace metricmap {

void to_json(nlohmann::json& j, const GridStatistics& s) {
  j = {{"total_cells", s.total_cells},
       {"occupied_cells", s.occupied_cells},
       {"empty_cells", s.empty_cells},
       {"mean_points_per_occupied_cell", s.mean_points_per_occupied_cell},
       {"points", s.points}};
}

void to_json(nlohmann::json& j, const OctreeStatistics& s) {
  j = {{"total_nodes", s.total_nodes},
       {"leaf_nodes", s.leaf_nodes},
       {"internal_nodes", s.internal_nodes},
       {"occupied_leaves", s.occupied_leaves},
       {"empty_leaves", s.empty_leaves},
       {"mean_points_per_occupied_leaf", s.mean_points_per_occupied_leaf},
       {"points", s.points},
       {"max_depth", s.max_depth}};
}

}  // namespace metricmap
