"""Bad input from Python: each case raises a Python exception (never a crash), or, for NaN/Inf
points, is skipped and counted as the library documents."""

import numpy as np
import pytest

import metricmap as mm

GOOD = np.random.default_rng(0).uniform(-5, 5, size=(1000, 3)).astype(np.float32)


def calls(points):
    """Every entry point that takes points."""
    return {
        "grid": lambda: mm.grid(points, 0.5),
        "octree": lambda: mm.octree(points, 10, 0.1),
        "log_odds": lambda: mm.LogOddsMap(0.5).insert_point_cloud(points, [0, 0, 0]),
        "odometry": lambda: mm.LidarOdometry().register_frame(points),
        "write_pcd": lambda: mm.write_pcd("/nonexistent-dir/x.pcd", points),
    }


BAD_POINTS = [
    ("int8 strings", np.array([["a", "b", "c"]]), TypeError),
    ("complex", np.zeros((4, 3), np.complex64), TypeError),
    ("object", np.array([[object()] * 3] * 2, dtype=object), TypeError),
    ("1-D", np.zeros(9, np.float32), ValueError),
    ("(N, 2)", np.zeros((4, 2), np.float32), ValueError),
    ("(N, 5)", np.zeros((4, 5), np.float32), ValueError),
    ("3-D", np.zeros((2, 2, 3), np.float32), ValueError),
    ("ragged list", [[1.0, 2.0, 3.0], [1.0, 2.0]], (TypeError, ValueError)),
    ("None", None, TypeError),
    ("huge float64", np.array([[1e300, 0, 0]] * 200), ValueError),
]


@pytest.mark.parametrize("name,points,exc", BAD_POINTS, ids=[b[0] for b in BAD_POINTS])
@pytest.mark.parametrize("call", ["grid", "octree", "log_odds", "odometry", "write_pcd"])
def test_bad_points(name, points, exc, call):
    with pytest.raises(exc):
        calls(points)[call]()


@pytest.mark.parametrize("call", ["grid", "octree", "odometry"])
def test_empty_points(call):
    with pytest.raises(ValueError):
        calls(np.zeros((0, 3), np.float32))[call]()


def test_empty_scan_is_a_no_op_for_the_log_odds_map():
    m = mm.LogOddsMap()
    assert m.insert_point_cloud(np.zeros((0, 3)), [0, 0, 0])["beams"] == 0


def test_nan_and_inf_points_are_skipped_and_counted():
    pts = GOOD.copy()
    pts[::10, 0] = np.nan
    pts[5::10, 2] = -np.inf
    skipped = 200
    assert mm.grid(pts, 0.5).statistics["skipped_points"] == skipped
    assert mm.octree(pts, 10, 0.1).statistics["skipped_points"] == skipped
    assert mm.LogOddsMap(0.5).insert_point_cloud(pts, [0, 0, 0])["non_finite"] == skipped
    nan_only = np.full((50, 3), np.nan, np.float32)
    assert mm.grid(nan_only, 1.0).statistics["occupied_cells"] == 0


def test_unaligned_and_byteswapped_arrays_are_converted():
    raw = np.zeros(len(GOOD) * 12 + 1, np.uint8)
    unaligned = np.frombuffer(raw.data, np.float32, count=len(GOOD) * 3, offset=1).reshape(-1, 3)
    unaligned[:] = GOOD
    assert not unaligned.flags.aligned
    big = GOOD.astype(">f4")
    ref = mm.grid(GOOD, 0.5)
    for a in (unaligned, big):
        g = mm.grid(a, 0.5)
        assert g.statistics == ref.statistics
        np.testing.assert_array_equal(g.means, ref.means)


def test_strided_views_are_read_correctly():
    wide = np.zeros((len(GOOD), 8), np.float32)
    wide[:, 2:5] = GOOD
    view = wide[:, 2:5]  # rows of 3, 32 bytes apart: copied
    np.testing.assert_array_equal(mm.grid(view, 0.5).means, mm.grid(GOOD, 0.5).means)
    neg = GOOD[::-1]  # negative row stride
    assert mm.grid(neg, 0.5).statistics == mm.grid(GOOD, 0.5).statistics


BAD_PARAMETERS = [
    ("cell 0", lambda: mm.grid(GOOD, 0.0), ValueError),
    ("cell < 0", lambda: mm.grid(GOOD, -1.0), ValueError),
    ("cell nan", lambda: mm.grid(GOOD, float("nan")), ValueError),
    ("cell inf", lambda: mm.grid(GOOD, float("inf")), ValueError),
    ("cell 1e-30", lambda: mm.grid(np.array([[-1e30, 0, 0], [1e30, 0, 0]], np.float32), 1e-30), mm.CapacityError),
    ("origin", lambda: mm.grid(GOOD, 1.0, origin="elsewhere"), ValueError),
    ("threads < 0", lambda: mm.grid(GOOD, 1.0, threads=-1), TypeError),
    ("max_points < 0", lambda: mm.octree(GOOD, -1), ValueError),
    ("min_cell < 0", lambda: mm.octree(GOOD, 10, -0.5), ValueError),
    ("root box shape", lambda: mm.octree(GOOD, 10, 0.1, root_box=([0, 0], [1, 1])), ValueError),
    ("root box nan", lambda: mm.octree(GOOD, 10, 0.1, root_box=([0, 0, np.nan], [1, 1, 1])), ValueError),
    ("root box inverted", lambda: mm.octree(GOOD, 10, 0.1, root_box=([1, 1, 1], [0, 0, 0])), ValueError),
    ("resolution 0", lambda: mm.LogOddsMap(0.0), ValueError),
    ("prob_hit 1", lambda: mm.LogOddsMap(0.1, prob_hit=1.0), ValueError),
    ("origin nan", lambda: mm.LogOddsMap().insert_point_cloud(GOOD, [np.nan, 0, 0]), ValueError),
    ("origin shape", lambda: mm.LogOddsMap().insert_point_cloud(GOOD, [0, 0]), ValueError),
    ("max_range nan", lambda: mm.LogOddsMap().insert_point_cloud(GOOD, [0, 0, 0], float("nan")), ValueError),
    ("far point", lambda: mm.LogOddsMap(0.01).insert_point_cloud(np.array([[1e7, 0, 0]], np.float32), [0, 0, 0]), mm.CapacityError),
    ("pcd format", lambda: mm.write_pcd("/tmp/x.pcd", GOOD, format="xml"), ValueError),
    ("depth dtype", lambda: mm.depth_to_cloud(np.zeros((4, 4), np.float32), 500, 500, 2, 2, 0.001), TypeError),
    ("depth shape", lambda: mm.depth_to_cloud(np.zeros((0, 4), np.uint16), 500, 500, 2, 2, 0.001), ValueError),
    ("depth scale", lambda: mm.depth_to_cloud(np.ones((4, 4), np.uint16), 500, 500, 2, 2, -1.0), ValueError),
    ("fx 0", lambda: mm.depth_to_cloud(np.ones((4, 4), np.uint16), 0, 500, 2, 2, 0.001), ValueError),
    ("odometry max_points_per_voxel", lambda: mm.LidarOdometry(max_points_per_voxel=0), ValueError),
]


@pytest.mark.parametrize("name,fn,exc", BAD_PARAMETERS, ids=[b[0] for b in BAD_PARAMETERS])
def test_bad_parameters(name, fn, exc):
    with pytest.raises(exc):
        fn()


BAD_FILES = [
    ("missing", "missing.pcd", None),
    ("directory", "", None),
    ("empty pcd", "empty.pcd", b""),
    ("garbage pcd", "garbage.pcd", b"\x00\xff" * 100),
    ("truncated header", "trunc.pcd", b"# .PCD v0.7\nVERSION 0.7\nFIELDS x y z\n"),
    ("bad bin size", "scan.bin", b"\x00" * 17),
    ("unknown extension", "cloud.xyz", b"1 2 3\n"),
]


@pytest.mark.parametrize("name,fname,content", BAD_FILES, ids=[b[0] for b in BAD_FILES])
@pytest.mark.parametrize("reader", [mm.read_points, mm.read_cloud, mm.cloud_info])
def test_bad_files(tmp_path, name, fname, content, reader):
    path = tmp_path / fname
    if content is not None:
        path.write_bytes(content)
    with pytest.raises(OSError) as e:
        reader(str(path))
    assert isinstance(e.value, mm.InputError) or isinstance(e.value, OSError)


def test_bad_image_and_camera_files(tmp_path):
    (tmp_path / "d.png").write_bytes(b"\x89PNG\r\n\x1a\nbroken")
    with pytest.raises(OSError):
        mm.read_depth_image(str(tmp_path / "d.png"))
    (tmp_path / "c.json").write_text("{")
    with pytest.raises(OSError):
        mm.read_camera(str(tmp_path / "c.json"))
    with pytest.raises(OSError):
        mm.read_scan_log(str(tmp_path / "none.clf"))


def test_closed_file_objects_are_refused():
    f = open(__file__)
    f.close()
    with pytest.raises(TypeError):
        mm.read_points(f)
