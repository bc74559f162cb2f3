"""The grid on the 3.7 M-point KITTI cloud from Python, as bench/bench_grid.cpp's
BM_OccupancyGridFresh (world-aligned 0.1 m cells, a new build each call, 1 or 2 threads).

Usage: PYTHONPATH=build/release/python /usr/bin/python3 python/bench/bench_grid.py [REPEATS]
Prints the median wall and CPU time per build for 1 and 2 threads, and the cell count."""

import pathlib
import statistics
import sys
import time

import numpy as np

import metricmap as mm

ROOT = pathlib.Path(__file__).resolve().parents[2]
velodyne = ROOT / "data/kitti_odometry_00/sequences/00/velodyne"
frames = np.concatenate([mm.read_points(str(velodyne / f"{f:06d}.bin")) for f in range(6)])
copies = []
while sum(len(c) for c in copies) < 3_000_000:  # as kittiCloud(): copies shifted 20 m in x
    c = frames.copy()
    c[:, 0] += np.float32(20.0 * len(copies))
    copies.append(c)
cloud = np.ascontiguousarray(np.concatenate(copies))  # (N, 4) float32: PCL's PointXYZ layout
repeats = int(sys.argv[1]) if len(sys.argv) > 1 else 15
print(f"{len(cloud)} points")
for threads in (1, 2):
    wall, cpu = [], []
    for _ in range(repeats):
        t0, c0 = time.perf_counter(), time.process_time()
        g = mm.grid(cloud, cell_size=0.1, origin="world", threads=threads)
        wall.append(time.perf_counter() - t0)
        cpu.append(time.process_time() - c0)
        del g
    print(
        f"threads:{threads} median {statistics.median(wall) * 1e3:.1f} ms wall, "
        f"{statistics.median(cpu) * 1e3:.1f} ms CPU (min {min(wall) * 1e3:.1f} ms wall)"
    )
g = mm.grid(cloud, cell_size=0.1, origin="world")
print(f"cells {len(g)}")
