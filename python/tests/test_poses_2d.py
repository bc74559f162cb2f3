"""One set of types: planar poses <-> 3D transforms as numpy builds them, the 2D SLAM's (N, 3)
trajectory and its log-order stamps fed straight to write_trajectory / evaluate_trajectory
(sorted by stamp there, as numpy sorts them), NaN for undefined figures, IntEnum states."""

import enum

import numpy as np
import pytest

import metricmap as mm


def se3_numpy(p):
    x, y, t = p
    c, s = np.cos(t), np.sin(t)
    return np.array([[c, -s, 0, x], [s, c, 0, y], [0, 0, 1, 0], [0, 0, 0, 1]])


def test_se2_se3_against_numpy():
    rng = np.random.default_rng(4)
    planar = np.column_stack([rng.uniform(-50, 50, (40, 2)), rng.uniform(-np.pi, np.pi, 40)])
    spatial = mm.se2_to_se3(planar)
    assert spatial.shape == (40, 4, 4)
    np.testing.assert_allclose(spatial, [se3_numpy(p) for p in planar], atol=1e-15)
    np.testing.assert_allclose(mm.se2_to_se3(planar[3]), se3_numpy(planar[3]), atol=1e-15)
    np.testing.assert_allclose(mm.se3_to_se2(spatial), planar, atol=1e-12)
    np.testing.assert_allclose(mm.se3_to_se2(spatial[5]), planar[5], atol=1e-12)
    # a 3D pose: its yaw is atan2(R10, R00), z and tilt dropped
    a, b = 0.3, -0.2
    tilt = np.array([[1, 0, 0], [0, np.cos(a), -np.sin(a)], [0, np.sin(a), np.cos(a)]]) @ np.array(
        [[np.cos(b), 0, np.sin(b)], [0, 1, 0], [-np.sin(b), 0, np.cos(b)]]
    )
    t = se3_numpy((1.0, 2.0, 0.7))
    t[:3, :3] = t[:3, :3] @ tilt
    t[2, 3] = 5.0
    np.testing.assert_allclose(mm.se3_to_se2(t), [1.0, 2.0, np.arctan2(t[1, 0], t[0, 0])], atol=1e-15)
    with pytest.raises(ValueError, match=r"\(3,\) or \(N, 3\)"):
        mm.se2_to_se3(np.zeros((2, 4)))
    with pytest.raises(ValueError, match=r"poses\[1\] is not finite"):
        mm.se2_to_se3([[0, 0, 0], [0, np.nan, 0]])


@pytest.fixture(scope="module")
def slam(data):
    source = mm.open_scan_source(data / "radish_clf_raw" / "intel.clf.bz2")
    run = mm.run_slam2d(source, frames=range(300))
    odometry = np.array([mm.se3_to_se2(source[k].odometry) for k in range(300)])
    return run, odometry


def test_slam_trajectory_feeds_evaluate_trajectory(slam):
    run, odometry = slam
    stamps = run.stamps
    assert run.trajectory.shape == (300, 3)
    assert (np.diff(stamps) < 0).any()  # the log's order is not the stamps' order
    e = mm.evaluate_trajectory(run.trajectory, odometry, estimate_stamps=stamps,
                               reference_stamps=stamps, align="none")
    order = np.argsort(stamps, kind="stable")
    assert e["paired_by"] == "stamps"
    np.testing.assert_array_equal(e["pairs"][0], order)  # indices of the arrays as given
    np.testing.assert_array_equal(e["pairs"][1], order)
    d = run.trajectory[order, :2] - odometry[order, :2]
    np.testing.assert_allclose(e["ate"]["translation"], np.hypot(d[:, 0], d[:, 1]), atol=1e-9)
    # the same as numpy's sorting before the call, with 3D poses
    f = mm.evaluate_trajectory(mm.se2_to_se3(run.trajectory[order]), mm.se2_to_se3(odometry[order]),
                               estimate_stamps=stamps[order], reference_stamps=stamps[order], align="none")
    np.testing.assert_allclose(e["rpe"]["translation"], f["rpe"]["translation"], atol=1e-12)
    np.testing.assert_allclose(e["ate"]["rotation_deg"], f["ate"]["rotation_deg"], atol=1e-9)


def test_slam_trajectory_written_as_tum_in_stamp_order(slam, tmp_path):
    run, _ = slam
    path = tmp_path / "slam.tum"
    mm.write_trajectory(path, run.trajectory, run.stamps, format="tum")
    rows = np.loadtxt(path)
    order = np.argsort(run.stamps, kind="stable")
    np.testing.assert_allclose(rows[:, 0], run.stamps[order], rtol=0, atol=1e-6)
    np.testing.assert_allclose(rows[:, 1:3], run.trajectory[order, :2], atol=1e-8)
    assert np.all(rows[:, 3] == 0)
    yaw = 2 * np.arctan2(rows[:, 6], rows[:, 7])  # qz, qw of a rotation about z
    np.testing.assert_allclose(np.angle(np.exp(1j * (yaw - run.trajectory[order, 2]))), 0, atol=1e-8)
    poses, stamps = mm.read_trajectory(path)
    np.testing.assert_allclose(mm.se3_to_se2(poses), run.trajectory[order], atol=1e-8)


def test_one_stamp_twice_is_named():
    poses = np.zeros((3, 3))
    with pytest.raises(ValueError, match="stamps: poses 0 and 2 have the same stamp"):
        mm.write_trajectory("/nonexistent/x.tum", poses, [5.0, 4.0, 5.0], format="tum")
    with pytest.raises(ValueError, match="estimate_stamps: poses 0 and 2 have the same stamp"):
        mm.evaluate_trajectory(poses, poses, estimate_stamps=[5.0, 4.0, 5.0], reference_stamps=[1, 2, 3])


def straight(length, step):
    n = int(round(length / step)) + 1
    return np.column_stack([np.arange(n) * step, np.zeros(n), np.zeros(n)])


def test_drift_of_a_short_path_is_nan():
    est = straight(19.7, 0.1)
    ref = est.copy()
    ref[:, 1] = 0.01 * np.sin(np.arange(len(ref)))
    e = mm.evaluate_trajectory(est, ref, align="none")
    drift = e["drift"]
    length = np.sum(np.hypot(*np.diff(ref[:, :2], axis=0).T))
    assert length < 100  # no KITTI segment (100 m to 800 m) fits
    assert drift["segments"] == 0
    assert drift["path_length"] == pytest.approx(length, rel=1e-9)
    assert np.isnan(drift["translation_percent"]) and np.isnan(drift["rotation_deg_per_m"])
    assert all(np.isnan(x["translation_percent"]) for x in drift["lengths"])
    # a path with segments has numbers
    long_est = straight(300.0, 1.0)
    long_ref = long_est.copy()
    long_ref[:, 0] *= 1.01
    g = mm.evaluate_trajectory(long_est, long_ref, align="none")["drift"]
    assert g["segments"] > 0 and np.isfinite(g["translation_percent"])
    assert g["translation_percent"] == pytest.approx(1.0, rel=0.01)  # about 1 m per 100 m


def test_cell_states_are_an_int_enum():
    assert issubclass(mm.CellState, enum.IntEnum)
    assert [mm.UNKNOWN, mm.FREE, mm.OCCUPIED] == [0, 1, 2]
    assert mm.OCCUPIED is mm.CellState.OCCUPIED and mm.CellState(1) is mm.FREE
    m = mm.LogOddsMap(0.5)
    m.insert_point_cloud(np.array([[3.0, 0.2, 0.2]]), origin=(0.2, 0.2, 0.2))
    probe = np.array([[3.1, 0.2, 0.2], [1.6, 0.2, 0.2], [-5.0, -5.0, -5.0]])
    states = m.states(probe)
    p = m.probability(probe)
    want = np.where(p > 0.5, 2, np.where(p < 0.5, 1, 0))  # numpy's reading of the probabilities
    np.testing.assert_array_equal(states, want)
    assert [mm.CellState(s) for s in states] == [mm.OCCUPIED, mm.FREE, mm.UNKNOWN]
