"""The grid-vs-octree study table (README) in a few lines: the four bundled scans under the
study's three configurations. Usage: python3 study_table.py [DATA_DIR]"""

import pathlib
import sys

import metricmap as mm

data = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parents[2] / "data")
rows = mm.compare(sorted((data / "ua_mapas_metricos_pcd").glob("*.pcd")))  # mm.STUDY_CONFIGS

print("| file | cell / min cell / max pts | grid total | occupied | mean | octree nodes | leaves | occupied | mean |")
print("|---|---|--:|--:|--:|--:|--:|--:|--:|")
for r in rows:
    c, g, o = r["config"], r["grid"], r["octree"]
    print(
        f"| {pathlib.Path(r['file']).stem} | {c['cell_size']} / {c['min_cell_size']} / {c['max_points']} "
        f"| {g['total_cells']} | {g['occupied_cells']} | {g['mean_points_per_occupied_cell']:.2f} "
        f"| {o['total_nodes']} | {o['leaf_nodes']} | {o['occupied_leaves']} | {o['mean_points_per_occupied_leaf']:.2f} |"
    )
