"""The Python surface's own rules for arguments (docs/RELIABILITY.md, "Python objects and
arguments"): an empty selection is refused, never "all"; NaN/inf arguments are refused; a
reflection is not a pose; an option the call would ignore is refused; and the exception types
are the documented ones. Each case names the call and the exception it must raise."""

import bz2
import math
import warnings

import numpy as np
import pytest

import metricmap as mm

INTEL = ("radish_clf_raw", "intel.clf.bz2")
REFLECTION = np.diag([1.0, 1.0, -1.0, 1.0])


@pytest.fixture(scope="module")
def intel(data):
    return mm.open_scan_source(data.joinpath(*INTEL))


@pytest.fixture
def folder(tmp_path):
    rng = np.random.default_rng(3)
    for k in range(3):
        np.save(tmp_path / f"scan_{k}.npy", rng.normal(size=(200, 3)).astype(np.float32))
    return tmp_path


def test_empty_selections_are_refused(intel):
    poses = mm.run_odometry(intel, frames=range(3))["sensor_poses"]
    cases = [
        lambda: mm.run_odometry(intel, frames=[]),
        lambda: mm.run_slam2d(intel, frames=[]),
        lambda: mm.reference_sensor_poses(intel, frames=np.array([], dtype=int)),
        lambda: mm.SequenceMapper(intel).build(poses[:1], frames=[]),
        lambda: mm.run_odometry(intel, frames=iter(())),
    ]
    for call in cases:
        with pytest.raises(ValueError, match="empty: nothing to process"):
            call()


def test_frames_may_be_any_iterable(intel):
    a = mm.run_odometry(intel, frames=(k for k in range(4)))
    b = mm.run_odometry(intel, frames=[0, 1, 2, 3])
    np.testing.assert_array_equal(a["poses"], b["poses"])
    np.testing.assert_array_equal(a["frames"], [0, 1, 2, 3])
    with pytest.raises(TypeError):
        mm.run_odometry(intel, frames="0-3")


@pytest.mark.parametrize("bad", [math.nan, math.inf, -math.inf])
def test_non_finite_arguments(bad):
    with pytest.raises(ValueError, match="not finite"):
        mm.camera_to_map(bad, 0.1)
    with pytest.raises(ValueError, match="not finite"):
        mm.camera_to_map(1.0, bad)
    with pytest.raises(ValueError, match="stamp"):
        mm.Slam2D().add_scan([0.0, 0.1], [1.0, 1.0], stamp=bad)


def test_per_point_times_must_be_finite(data):
    src = mm.open_scan_source(data / "kitti_odometry_00")
    pts = np.array(src[0].points)
    for times in (np.full(len(pts), np.nan), np.r_[np.inf, np.zeros(len(pts) - 1)]):
        with pytest.raises(ValueError, match="not finite"):
            mm.LidarOdometry(deskew=True).register_frame(pts, times)
    with pytest.raises(ValueError, match="deskew"):  # times the odometry would not use
        mm.LidarOdometry(deskew=False).register_frame(pts, np.zeros(len(pts)))


def test_a_reflection_is_not_a_pose(intel):
    pts = np.random.default_rng(0).uniform(-1, 1, (100, 3))
    with pytest.raises(ValueError, match="not a rotation"):
        mm.HeightMap().add_frame(pts, REFLECTION)
    with pytest.raises(ValueError, match="not a rotation"):
        mm.Slam2D(sensor_to_base=REFLECTION)
    with pytest.raises(ValueError, match="not a rotation"):
        mm.Slam2D().add_scan([0.0], [1.0], odometry=REFLECTION)
    with pytest.raises(ValueError, match="not a rotation"):
        mm.SequenceMapper(intel).build(np.stack([np.eye(4), REFLECTION]), frames=[0, 1])
    with pytest.raises(ValueError, match="not a rotation"):
        mm.write_trajectory("/nonexistent/never.txt", REFLECTION[None])


def test_options_a_call_would_ignore(data, folder, tmp_path, intel):
    log = data.joinpath(*INTEL)
    (tmp_path / "t.txt").write_text("0\n1\n2\n")
    cases = [
        lambda: mm.open_scan_source(folder, sequence="01"),
        lambda: mm.open_scan_source(folder, topic="/points"),
        lambda: mm.open_scan_source(log, times=tmp_path / "t.txt"),
        lambda: mm.open_scan_source(log, reference_poses=tmp_path / "t.txt"),
        lambda: mm.evaluate_trajectory(np.eye(4)[None].repeat(3, 0), np.eye(4)[None].repeat(3, 0),
                                       max_time_diff=0.1),
        lambda: mm.evaluate_trajectory(np.eye(4)[None].repeat(3, 0), np.eye(4)[None].repeat(3, 0),
                                       estimate_stamps=[0.0, 1.0, 2.0]),
        lambda: mm.write_trajectory(tmp_path / "k.txt", np.eye(4)[None], stamps=[0.0]),
        lambda: mm.compare([data / "pcl_test_pcd" / "bunny.pcd"],
                           [{"cell_size": 1, "min_cell_size": 1, "max_points": 100, "cel_size": 2}]),
        lambda: mm.compare([data / "pcl_test_pcd" / "bunny.pcd"],
                           [{"cell_size": 1, "min_cell_size": 1, "max_points": 2.5}]),
        lambda: mm.SequenceMapper(intel).build(
            mm.run_odometry(intel, frames=range(2))["sensor_poses"], frames=[0, 1]).global_cloud(),
    ]
    for k, call in enumerate(cases):
        with pytest.raises(ValueError):
            call()
    assert not (tmp_path / "k.txt").exists()
    assert len(mm.open_scan_source(folder, sequence=None)) == 3


def test_tum_stamps_that_would_not_read_back(tmp_path):
    poses = np.eye(4)[None].repeat(3, 0)
    for stamps in ([0.0, 2.0, 0.0], [0.0, 1.0, 1.0 + 1e-12], [0.0, np.nan, 2.0]):
        with pytest.raises(ValueError, match="stamp"):
            mm.write_trajectory(tmp_path / "t.tum", poses, stamps=stamps, format="tum")
        assert not (tmp_path / "t.tum").exists()
    mm.write_trajectory(tmp_path / "t.tum", poses, stamps=[0.0, 1.0, 2.0], format="tum")
    got, stamps = mm.read_trajectory(tmp_path / "t.tum")
    np.testing.assert_array_equal(stamps, [0.0, 1.0, 2.0])


def test_read_scan_log_warns_of_skipped_lines(data, tmp_path):
    lines = bz2.open(data.joinpath(*INTEL), "rt").read().splitlines()
    flaser = [line for line in lines if line.startswith("FLASER")][:3]
    path = tmp_path / "log.clf"
    path.write_text("\n".join(flaser + ["FLASER 180 not numbers at all"]) + "\n")
    with pytest.warns(UserWarning, match="skipped 1 malformed"):
        scans = mm.read_scan_log(path)
    assert len(scans) == 3
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        path.write_text("\n".join(flaser) + "\n")
        assert len(mm.read_scan_log(path)) == 3


def test_exception_types(data):
    with pytest.raises(mm.InputError, match="floor fit"):  # a ValueError, not RuntimeError
        mm.fit_floor(np.random.default_rng(0).uniform(-1, 1, (50, 3)))
    with pytest.raises(TypeError, match="single path"):
        mm.compare(str(data / "pcl_test_pcd" / "bunny.pcd"))
    with pytest.raises(ValueError, match="no beams"):
        mm.Slam2D().add_scan([], [])
