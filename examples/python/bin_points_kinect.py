"""Active Neural SLAM's bin_points on the bundled Kinect frame, drawn with matplotlib.
Usage: python3 bin_points_kinect.py [OUT.png]"""

import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import metricmap as mm  # noqa: E402

data = pathlib.Path(__file__).resolve().parents[2] / "data" / "pcl_grabber_kinect_depth"
out = sys.argv[1] if len(sys.argv) > 1 else "kinect_bin_points.png"

depth = mm.read_depth_image(str(data / "tiff/frame_20121214T142255.814212_depth.tiff"))
k = mm.read_camera(str(data / "xml/frame_20121214T142255.814212.xml"))
xyz = mm.depth_to_cloud(depth, k["fx"], k["fy"], k["cx"], k["cy"], 0.001)  # (H, W, 3) metres

# ANS's geocentric centimetres: x right (map centred), y forward, z up (camera 1 m high).
map_size, resolution = 160, 5.0  # 8 m x 8 m at 5 cm
XYZ = np.stack([xyz[..., 0] * 100 + map_size * resolution / 2, xyz[..., 2] * 100, 100 - xyz[..., 1] * 100], axis=-1)
counts, isvalid = mm.bin_points(XYZ, map_size, [25, 150], resolution)
print(f"{int(isvalid.sum())} of {isvalid.size} points binned; counts {counts.shape} {counts.dtype}")

obstacles = counts[..., 1] > 0  # the agent's height band
explored = counts.sum(axis=-1) > 0
fig, ax = plt.subplots(1, 2, figsize=(9, 4.5))
ax[0].imshow(depth, cmap="viridis")
ax[0].set_title("depth (mm)")
ax[1].imshow(explored * 0.4 + obstacles * 0.6, origin="lower", cmap="gray_r")
ax[1].set_title("bin_points: explored / obstacles")
fig.savefig(out, dpi=80)
print(f"wrote {out}")
