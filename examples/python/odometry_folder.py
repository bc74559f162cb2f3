"""LiDAR odometry on a folder of scans (.bin/.pcd/.ply), printing KITTI pose rows.
Usage: python3 odometry_folder.py [FOLDER]"""

import pathlib
import sys

import numpy as np

import metricmap as mm

default = pathlib.Path(__file__).resolve().parents[2] / "data/kitti_odometry_00/sequences/00/velodyne"
folder = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else default)
scans = sorted(p for p in folder.iterdir() if p.suffix in (".bin", ".pcd", ".ply"))

first = mm.read_points(str(scans[0]))
profile = mm.sensor_profile(first)  # the range window and voxel `metricmap odometry` picks
odometry = mm.LidarOdometry(
    max_range=profile["max_range"], min_range=profile["min_range"], voxel_size=profile["voxel_size"]
)
for scan in scans:
    pose = odometry.register_frame(mm.read_points(str(scan)))
    print(" ".join(f"{v:.6e}" for v in pose[:3].ravel()))
steps = np.linalg.norm(np.diff(odometry.poses[:, :3, 3], axis=0), axis=1)
print(f"# {len(scans)} scans, {steps.sum():.2f} m travelled", file=sys.stderr)
