#!/usr/bin/env python3
"""metricmap.bin_points against Active Neural SLAM's numpy bin_points (python/tests/
test_bin_points.py writes it from its published definition) on the bundled 640 x 480 Kinect
frame, float32 and float64, a new output per call as a user gets it: median of N calls each,
in one process, and the ratio.

    PYTHONPATH=build/release/python /usr/bin/python3 bench/bin_points_speed.py [N]
"""
import pathlib
import statistics
import sys
import time

import numpy as np

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "python" / "tests"))
import metricmap as mm  # noqa: E402
from test_bin_points import KINECT, ans_bin_points, frame_cm  # noqa: E402


def median_ms(f, args, n):
    times = []
    for _ in range(n):
        start = time.perf_counter()
        f(*args)
        times.append(time.perf_counter() - start)
    return statistics.median(times) * 1e3


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 30
    xyz = frame_cm(ROOT / "data", *KINECT[0], 0.001)
    for dtype in (np.float32, np.float64):
        args = (xyz.astype(dtype), 480, [25, 150], 5)
        ref, got = ans_bin_points(*args), mm.bin_points(*args)
        assert all(np.array_equal(a, b) for a, b in zip(ref, got)), "results differ"
        t_np, t_mm = median_ms(ans_bin_points, args, n), median_ms(mm.bin_points, args, n)
        print(f"{np.dtype(dtype).name}: numpy {t_np:.2f} ms, metricmap {t_mm:.2f} ms, {t_np / t_mm:.1f}x")


if __name__ == "__main__":
    main()
