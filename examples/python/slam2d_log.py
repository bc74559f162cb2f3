"""2D SLAM on a CARMEN log: trajectory, loop closures and the map, drawn with matplotlib.
Usage: python3 slam2d_log.py [LOG] [SCANS] [out.png]   (default: the first 600 scans of the
Intel Research Lab log bundled in data/radish_clf_raw)"""

import pathlib
import sys

import numpy as np

import metricmap as mm

repo = pathlib.Path(__file__).resolve().parents[2]
log = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else repo / "data/radish_clf_raw/intel.clf.bz2"
scans = int(sys.argv[2]) if len(sys.argv) > 2 else 600
out = pathlib.Path(sys.argv[3]) if len(sys.argv) > 3 else pathlib.Path("slam2d.png")

source = mm.open_scan_source(log)
config = mm.Slam2DConfig(scans_per_submap=30)  # smaller submaps: loops within a short prefix
slam = mm.run_slam2d(source, frames=range(min(scans, len(source))), config=config)

xy = slam.trajectory[:, :2]  # (N, 3): x, y (m), theta (rad) of the robot per scan
m = slam.map_image()  # map_server's view: (H, W) uint8, row 0 at the top
print(f"{len(xy)} scans, {slam.stats['nodes']} nodes, {len(slam.loops)} loop closures, "
      f"{slam.map()['occupied_cells']} occupied cells, path {np.linalg.norm(np.diff(xy, axis=0), axis=1).sum():.1f} m")
slam.write_map(out.with_suffix(".pgm"))  # + .yaml: what `metricmap slam2d --out-map` writes

import matplotlib.pyplot as plt  # noqa: E402

h, w = m["image"].shape
x0, y0 = m["origin"]
extent = [x0, x0 + w * m["resolution"], y0, y0 + h * m["resolution"]]
fig, ax = plt.subplots(figsize=(8, 8 * h / w + 0.5))
ax.imshow(m["image"], cmap="gray", extent=extent, vmin=0, vmax=255)
ax.plot(xy[:, 0], xy[:, 1], "b-", lw=0.8)
nodes = slam.graph.poses
for loop in slam.loops:
    a, b = nodes[loop["anchor"]], nodes[loop["node"]]
    ax.plot([a[0], b[0]], [a[1], b[1]], "r-", lw=0.6)
ax.set_xlabel("x (m)")
ax.set_ylabel("y (m)")
fig.savefig(out, dpi=120, bbox_inches="tight")
print(f"wrote {out} and {out.with_suffix('.pgm')}")
