# Figures of docs/DISTANCE.md: a horizontal slice of the KITTI field and the Intel costmap.
# usage: distance_figures.py k.npy k.json cost.pgm OUTDIR (cost.json: the report of the costmap run)
import sys, json, numpy as np, matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
field, report, costmap, out = sys.argv[1:5]
f = np.load(field); r = json.load(open(report))
ox, oy, oz = r["origin"]; res = r["resolution"]
k = int(round((0.5 - oz) / res))          # the slice 0.5 m above the map frame's origin
fig, ax = plt.subplots(figsize=(9, 7))
im = ax.imshow(f[:, :, k].T, origin="lower", cmap="viridis",
               extent=[ox - res / 2, ox + (f.shape[0] - 0.5) * res, oy - res / 2, oy + (f.shape[1] - 0.5) * res])
fig.colorbar(im, ax=ax, label="distance to the nearest occupied voxel (m)")
ax.set_xlabel("x (m)"); ax.set_ylabel("y (m)")
ax.set_title(f"KITTI 00 frames 0-5, 0.2 m voxels, z = {oz + k * res:.1f} m, clamped at {r['max_distance']} m")
fig.tight_layout(); fig.savefig(out + "/distance_kitti_slice.png", dpi=80)
raw = open(costmap, "rb").read()
w, h = json.load(open(costmap[:-4] + ".json"))["shape"]; c = np.frombuffer(raw[-w * h:], np.uint8).reshape(h, w)
rgb = np.zeros((h, w, 3), np.uint8)
g = c.astype(float) / 252.0
rgb[...] = (255 * (1 - np.clip(g, 0, 1)))[..., None].astype(np.uint8)
rgb[c == 0] = (255, 255, 255); rgb[c == 253] = (80, 140, 255); rgb[c == 254] = (0, 0, 0); rgb[c == 255] = (200, 200, 200)
rgb[(c > 0) & (c < 253)] = np.stack([255 * np.ones_like(g), 255 * (1 - g), 255 * (1 - g)], -1)[(c > 0) & (c < 253)].astype(np.uint8)
fig, ax = plt.subplots(figsize=(8, 8)); ax.imshow(rgb); ax.axis("off")
ax.set_title("Intel Research Lab (slam2d map), nav2 inflation costmap: lethal black, inscribed blue,\ninflated red fading to white, unknown grey")
fig.tight_layout(); fig.savefig(out + "/distance_intel_costmap.png", dpi=80)
