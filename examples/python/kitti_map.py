"""A KITTI map: the bundled scans at their reference poses -> one cloud -> a 0.2 m grid ->
a top-down occupancy picture. Usage: python3 kitti_map.py [OUT.png]"""

import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import metricmap as mm  # noqa: E402

root = pathlib.Path(__file__).resolve().parents[2] / "data" / "kitti_odometry_00"
out = sys.argv[1] if len(sys.argv) > 1 else "kitti_map.png"

calib = {line.split(":")[0]: line.split(":")[1] for line in (root / "sequences/00/calib.txt").read_text().splitlines() if ":" in line}
tr = np.vstack([np.fromstring(calib["Tr"], sep=" ").reshape(3, 4), [0, 0, 0, 1]])  # velodyne -> camera
poses = np.loadtxt(root / "poses/00.txt").reshape(-1, 3, 4)  # camera k -> camera 0

clouds = []
for k, scan in enumerate(sorted((root / "sequences/00/velodyne").glob("*.bin"))):
    p = mm.read_points(str(scan)).astype(np.float64)  # x, y, z, 1: homogeneous already
    p = p[np.linalg.norm(p[:, :3], axis=1) > 2.5]
    pose = np.vstack([poses[k], [0, 0, 0, 1]]) @ tr
    clouds.append((p @ pose.T)[:, :3])
world = np.concatenate(clouds).astype(np.float32)  # camera 0 frame: x right, y down, z forward

g = mm.grid(world, cell_size=0.2, origin="world")
hits = np.zeros((g.dims[2], g.dims[0]))
i = g.indices - np.array(g.min_index)
np.add.at(hits, (i[:, 2], i[:, 0]), g.counts)  # project the cells on the x-z plane
print(f"{len(world)} points, {len(g)} occupied cells of {g.cell_size} m, map {hits.shape}")
plt.figure(figsize=(6, 6))
plt.imshow(np.log1p(hits), origin="lower", cmap="gray_r")
plt.title("KITTI 00, frames 0-%d" % (len(clouds) - 1))
plt.savefig(out, dpi=80)
print(f"wrote {out}")
