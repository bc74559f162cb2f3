"""The Python entry points of the library rules the fifth hardening pass added: tiny beam cuts,
nothing done, files the reader would refuse, poses and numbers beyond their bounds, values given
then replaced. Each raises the documented exception with a message naming the value."""

import math

import numpy as np
import pytest

import metricmap as mm

I4 = np.eye(4)


def ring_folder(tmp, radius=8.0, n=400, scans=2):
    a = 2 * math.pi * np.arange(n) / n
    pts = np.stack([radius * np.cos(a), radius * np.sin(a), 0.1 * (np.arange(n) % 7)], 1).astype(np.float32)
    for k in range(scans):
        np.save(tmp / f"{k:03d}.npy", pts)
    return tmp


def refusals(tmp):
    pts = np.array([[1.0, 0.0, 0.0], [2.0, 1.0, 0.5]], np.float32)
    three = np.stack([I4, I4, I4])
    return [
        # tiny beam cuts
        ("log-odds max_range 1e-23", lambda: mm.LogOddsMap(0.1).insert_point_cloud(pts, [0, 0, 0], max_range=1e-23),
         ValueError, "max_range must be >= 0.001 m"),
        ("log-odds max_range 1e-4", lambda: mm.LogOddsMap(0.1).insert_point_cloud(pts, [0, 0, 0], max_range=1e-4),
         ValueError, "got 0.0001"),
        # nothing done
        ("optimise an empty graph", lambda: mm.PoseGraph(2).optimize(), ValueError, "0 vertices and no edge"),
        # files the reader would refuse
        ("TUM stamps not increasing", lambda: mm.write_trajectory(tmp / "t.txt", three, [0.0, 2.0, 1.0], format="tum"),
         ValueError, "stamps must increase strictly"),
        ("TUM stamps equal as written", lambda: mm.write_trajectory(tmp / "t.txt", three, [0.0, 1e-10, 1.0],
                                                                    format="tum"), ValueError, "as written"),
        # poses and numbers beyond their bounds
        ("graph vertex 1e30", lambda: mm.PoseGraph(2).add_vertex(0, [1e30, 0, 0]), ValueError, "beyond 1000000 m"),
        ("graph theta 1e17", lambda: mm.PoseGraph(2).add_vertex(0, [0, 0, 1e17]), ValueError, "theta 1e+17"),
        ("depth scale underflow", lambda: mm.depth_to_cloud(np.full((4, 5), 7, np.uint16), 500, 500, 2, 2, 1e-300),
         ValueError, "below float range"),
        ("grid cell 1e39", lambda: mm.grid(pts, 1e39), ValueError, "cell_size 1e+39"),
        ("grid finer than float32", lambda: mm.grid(np.array([[1e7, 0, 0], [10000001, 0, 0]], np.float32), 0.1),
         mm.CapacityError, "finer than float32"),
        ("height map reflection", lambda: mm.HeightMap(map_size=64).add_frame(pts, np.diag([1.0, 1.0, -1.0, 1.0])),
         ValueError, "rotation"),
        # a value given, then replaced
        ("given min_range above the chosen window", lambda: mm.run_odometry(str(ring_folder(tmp / "rings")),
                                                                            min_range=50.0),
         ValueError, "min_range 50 m (given)"),
    ]


@pytest.mark.parametrize("index", range(12))
def test_refused_with_a_message_naming_the_value(tmp_path, index):
    (tmp_path / "rings").mkdir()
    name, call, error, needle = refusals(tmp_path)[index]
    with pytest.raises(error) as e:
        call()
    assert needle in str(e.value), (name, str(e.value))
    assert not (tmp_path / "t.txt").exists(), name


def test_the_limits_themselves_are_accepted(tmp_path):
    pts = np.array([[1.0, 0.0, 0.0], [2.0, 1.0, 0.5]], np.float32)
    m = mm.LogOddsMap(0.1)
    m.insert_point_cloud(pts, [0, 0, 0], max_range=0.001)
    g = mm.PoseGraph(2)
    g.add_vertex(0, [1e6, -1e6, 1e6])
    mm.write_trajectory(tmp_path / "t.txt", np.stack([I4, I4]), [0.0, 1e-9], format="tum")
    poses, stamps = mm.read_trajectory(tmp_path / "t.txt")
    np.testing.assert_allclose(stamps, [0.0, 1e-9], atol=1e-12)
