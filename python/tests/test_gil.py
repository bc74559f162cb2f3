"""The GIL is released while the library computes: another Python thread keeps running."""

import re
import threading
import time

import numpy as np

import metricmap as mm


def ticks_inside(calls):
    """Run the callables one after another in a worker thread while this thread ticks; return
    how many ticks fell inside each call (a GIL holder allows none during its call)."""
    spans, done = [], threading.Event()

    def work():
        for fn in calls:
            t0 = time.perf_counter()
            fn()
            spans.append((t0, time.perf_counter()))
        done.set()

    ticks = []
    t = threading.Thread(target=work)
    t.start()
    while not done.is_set():
        ticks.append(time.perf_counter())
        time.sleep(0)  # yields the GIL
    t.join()
    ticks = np.array(ticks)
    return [int(((ticks > a) & (ticks < b)).sum()) for a, b in spans]


def test_grid_and_octree_release_the_gil(data):
    frames = [mm.read_points(str(data / f"kitti_odometry_00/sequences/00/velodyne/{i:06d}.bin")) for i in range(6)]
    cloud = np.concatenate(frames * 3)  # ~2.2 M points: builds of a few hundred ms
    calls = [lambda: mm.grid(cloud, 0.1, origin="world", threads=1), lambda: mm.octree(cloud, 20, 0.2, threads=1)]
    assert min(ticks_inside(calls * 2)) >= 50  # observed: thousands


def test_the_measure_sees_a_gil_holder():
    # re's matcher keeps the GIL for its whole (catastrophically backtracking) search
    pattern = re.compile(r"(x+x+)+y")
    assert max(ticks_inside([lambda: pattern.search("x" * 21)] * 2)) <= 2  # the tick at its start
