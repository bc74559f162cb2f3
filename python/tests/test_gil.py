"""The GIL is released while the library computes: another Python thread keeps running."""

import re
import threading
import time

import numpy as np

import metricmap as mm


def ticks_inside(calls):
    """Run the callables one after another in a worker thread while this thread ticks; return
    how many ticks fell inside the middle half of each call (a GIL holder allows none there)."""
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
    # The middle half of each call only: at its two ends the worker runs bytecode, where the
    # interpreter may hand the GIL to this thread for a switch interval (5 ms) or, on a loaded
    # machine, until the OS schedules the worker again (observed: up to 264 ticks).
    inner = [(a + (b - a) / 4, b - (b - a) / 4) for a, b in spans]
    return [int(((ticks > a) & (ticks < b)).sum()) for a, b in inner]


def test_grid_and_octree_release_the_gil(data):
    frames = [mm.read_points(str(data / f"kitti_odometry_00/sequences/00/velodyne/{i:06d}.bin")) for i in range(6)]
    cloud = np.concatenate(frames * 3)  # ~2.2 M points: builds of a few hundred ms
    calls = [lambda: mm.grid(cloud, 0.1, origin="world", threads=1), lambda: mm.octree(cloud, 20, 0.2, threads=1)]
    assert min(ticks_inside(calls * 2)) >= 50  # observed: thousands


def test_the_measure_sees_a_gil_holder():
    # re's matcher keeps the GIL for its whole (catastrophically backtracking) search
    pattern = re.compile(r"(x+x+)+y")
    assert max(ticks_inside([lambda: pattern.search("x" * 21)] * 2)) <= 2  # the tick at its start


def noisy_chain(n, seed):
    """A chain of n 2D poses with a loop edge, its initial guess off by noise: some ms to solve."""
    rng = np.random.default_rng(seed)
    graph = mm.PoseGraph(2)
    for k in range(n):
        graph.add_vertex(k, [k * 0.1 + rng.normal(scale=0.3), rng.normal(scale=0.3), rng.normal(scale=0.1)])
    for k in range(n - 1):
        graph.add_edge(k, k + 1, [0.1, 0.0, 0.0], np.eye(3) * 100)
    graph.add_edge(0, n - 1, [(n - 1) * 0.1, 0.0, 0.0], np.eye(3) * 100, loop=True)
    return graph


def test_sequence_slam_and_posegraph_release_the_gil(data):
    src = mm.open_scan_source(data / "kitti_odometry_00")
    intel = data / "radish_clf_raw" / "intel.clf.bz2"
    graph = noisy_chain(3000, 1)
    calls = [
        lambda: mm.run_odometry(src, threads=1),
        lambda: mm.run_slam2d(intel, frames=range(120)),
        lambda: graph.optimize(max_iterations=20),
    ]
    assert min(ticks_inside(calls)) >= 5  # observed: thousands
