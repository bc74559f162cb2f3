"""Our own messages for calls the binding cannot match (the unknown keywords and the parameters
the function takes, never the arguments' values), sensor_profile() as LidarOdometry's arguments,
repr() with values, ScanSource slices."""

import pickle

import numpy as np
import pytest

import metricmap as mm


@pytest.fixture(scope="module")
def scan(data):
    return mm.read_points(data / "kitti_odometry_00/sequences/00/velodyne/000000.bin")


def test_unknown_keywords_are_named(scan):
    with pytest.raises(TypeError) as e:
        mm.grid(scan, voxel_size=0.5)
    msg = str(e.value)
    assert msg.startswith("grid() got unknown keyword argument 'voxel_size'; it takes: points, cell_size")
    assert len(msg) < 200 and "array" not in msg  # no dump of the points
    with pytest.raises(TypeError, match=r"LidarOdometry\(\) got unknown keyword arguments 'max_rang', 'foo'"):
        mm.LidarOdometry(max_rang=3, foo=1)
    with pytest.raises(TypeError, match=r"LogOddsMap\(\) got unknown keyword argument 'resolutio'; it takes: resolution"):
        mm.LogOddsMap(resolutio=0.1)
    with pytest.raises(TypeError, match=r"grid\(\) cannot take \(ndarray, str, str, str\)"):
        mm.grid(scan, "a", "b", "c")
    # errors raised by the functions themselves pass unchanged
    with pytest.raises(ValueError, match="origin must be"):
        mm.grid(scan, origin="centre")
    assert pickle.loads(pickle.dumps(mm.grid)) is mm.grid


def test_sensor_profile_is_lidar_odometry_arguments(scan, data):
    profile = mm.sensor_profile(scan)
    odo = mm.LidarOdometry(**profile)
    for k in (0, 1, 2):
        odo.register_frame(mm.read_points(data / f"kitti_odometry_00/sequences/00/velodyne/{k:06d}.bin"))
    # the same as the arguments spelled out, each the profile's number
    spelled = mm.LidarOdometry(max_range=profile["max_range"], min_range=profile["min_range"],
                               voxel_size=profile["voxel_size"], coarse_voxel_size=profile["coarse_voxel_size"],
                               max_threshold=profile["max_threshold"], convergence=profile["convergence"])
    for k in (0, 1, 2):
        spelled.register_frame(mm.read_points(data / f"kitti_odometry_00/sequences/00/velodyne/{k:06d}.bin"))
    np.testing.assert_array_equal(odo.poses, spelled.poses)
    r = np.linalg.norm(scan[:, :3].astype(np.float64), axis=1)
    stats = mm.sensor_profile(scan, statistics=True)
    assert stats["median_range"] == pytest.approx(np.median(r[r > 0]), rel=1e-3)
    assert {k: v for k, v in stats.items() if k in profile} == profile
    assert f"max_range={profile['max_range']!r}" in repr(odo) and "3 scans registered" in repr(odo)


def test_reprs_show_values(data):
    g = mm.PoseGraph(2)
    g.add_vertex(0, [0, 0, 0])
    g.add_vertex(1, [1, 0, 0])
    g.add_edge(0, 1, [1, 0, 0], np.eye(3), loop=True)
    assert repr(g) == "<metricmap.PoseGraph 2D, 2 vertices, 1 edges (1 loops)>"
    h = mm.HeightMap(resolution=0.05, map_size=40)
    assert "40 x 40 cells" in repr(h) and "3 height bins" in repr(h)
    for obj in (mm.LidarOdometry(), h, mm.open_scan_source(data / "kitti_odometry_00")):
        assert " at 0x" not in repr(obj)


def test_scan_source_slices(data):
    src = mm.open_scan_source(data / "kitti_odometry_00")
    n = len(src)
    for sl in (slice(None), slice(1, None), slice(None, None, 2), slice(-2, None), slice(None, None, -1), slice(5, 1)):
        got = src[sl]
        want = list(range(n))[sl]
        assert isinstance(got, list) and [s.index for s in got] == want
        for s in got:
            np.testing.assert_array_equal(s.points, src[s.index].points)
    with pytest.raises(TypeError, match="integers or slices, got str"):
        src["0"]
    with pytest.raises(ValueError, match="slice step cannot be zero"):
        src[::0]
