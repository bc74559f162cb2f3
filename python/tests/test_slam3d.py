"""metricmap.Slam3D and run_slam3d: loop closure of the NCLT reverse revisit on the reference
poses with an injected drift (the pipeline's own loop relations as the oracle), no loop on the
KITTI frames, range checks, progress and cancellation."""
import pathlib

import numpy as np
import pytest

import metricmap as mm

ROOT = pathlib.Path(__file__).resolve().parents[2]
NCLT = ROOT.parent / "shared" / "data" / "nclt_2013_01_10_keyframes"
KITTI = ROOT / "data" / "kitti_odometry_00"


def need_nclt():
    if not NCLT.exists():
        pytest.skip(f"{NCLT} is missing")


def yaw(deg):
    t = np.eye(4)
    a = np.radians(deg)
    t[:2, :2] = [[np.cos(a), -np.sin(a)], [np.sin(a), np.cos(a)]]
    return t


def test_config_is_range_checked():
    c = mm.Slam3DConfig(loop_radius=5.0)
    assert c.loop_radius == 5.0
    with pytest.raises(ValueError, match="voxel"):
        c.voxel = 0.0
    with pytest.raises(TypeError):
        c.loop_every = 1.5
    with pytest.raises(TypeError):
        mm.Slam3DConfig(no_such=1)


def test_closes_the_reverse_revisit_under_drift():
    need_nclt()
    source = mm.open_scan_source(str(NCLT))
    ref = np.loadtxt(NCLT / "poses.txt").reshape(-1, 3, 4)
    ref = np.concatenate([ref, np.tile([[[0, 0, 0, 1.0]]], (len(ref), 1, 1))], axis=1)
    first, last = 340, 560
    slam = mm.Slam3D()
    pose = ref[first].copy()
    poses = []
    for i in range(first, last + 1):
        if i > first:
            step = np.linalg.inv(ref[i - 1]) @ ref[i]
            step[:3, 3] *= 1.01
            pose = pose @ yaw(0.03) @ step
        poses.append(pose.copy())
        slam.add_scan(source[i].points, pose)
    slam.finish()
    assert slam.verified_loops >= 3
    est = slam.poses
    # The pipeline's NDT loop relations T_i^-1 T_j, within the subset.
    errs, errs_drift = [], []
    for row in np.loadtxt(NCLT / "reference" / "loops.txt"):
        i, j = int(row[0]), int(row[1])
        if not (first <= i <= last and first <= j <= last):
            continue
        rel = np.eye(4)
        from scipy.spatial.transform import Rotation

        rel[:3, :3] = Rotation.from_quat(row[6:10]).as_matrix()
        rel[:3, 3] = row[3:6]
        for p, out in ((est, errs), (poses, errs_drift)):
            e = np.linalg.inv(rel) @ np.linalg.inv(p[i - first]) @ p[j - first]
            out.append(np.linalg.norm(e[:3, 3]))
    assert len(errs) >= 10
    assert np.mean(errs_drift) > 0.5
    # 0.35 m on this short subset (its ends have fewer loops); drifted: over 0.5 m.
    assert np.mean(errs) < 0.45
    for loop in slam.loops:
        if loop["accepted"]:
            truth = np.linalg.inv(ref[loop["from"] + first]) @ ref[loop["to"] + first]
            e = np.linalg.inv(truth) @ loop["relation"]
            assert np.linalg.norm(e[:3, 3]) < 0.5


def test_run_on_kitti_frames_finds_no_loop_and_reports_progress():
    calls = []
    r = mm.run_slam3d(str(KITTI), progress=lambda done, total: calls.append((done, total)))
    assert r["poses"].shape == (6, 4, 4)
    assert r["slam"].verified_loops == 0
    assert calls and calls[-1] == (6, 6)
    # Without a loop the trajectory is the odometry's (run_odometry: the same convention).
    odo = mm.run_odometry(str(KITTI))
    assert np.allclose(r["poses"], odo["poses"], atol=1e-9)
    assert np.allclose(r["odometry_poses"], odo["poses"], atol=1e-9)


def test_run_is_cancelled_by_the_progress_callback():
    def stop(done, total):
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        mm.run_slam3d(str(KITTI), progress=stop)


def test_bad_input_is_refused():
    slam = mm.Slam3D()
    with pytest.raises(ValueError):
        slam.add_scan(np.zeros((10, 3)), np.eye(3))
    bad = np.eye(4)
    bad[0, 3] = np.nan
    with pytest.raises(ValueError):
        slam.add_scan(np.zeros((10, 3)), bad)
    with pytest.raises(ValueError):
        mm.run_slam3d(str(KITTI), frames=[3, 2])


def test_a_refused_scan_leaves_the_object_as_it_was():
    rng = np.random.default_rng(2)
    points = rng.uniform(-10, 10, (500, 3))
    slam = mm.Slam3D()
    slam.add_scan(points, np.eye(4))
    far = np.eye(4)
    far[0, 3] = 1e30
    reflection = np.diag([1.0, 1.0, -1.0, 1.0])
    for pose, needle in ((far, "beyond"), (reflection, "not a rotation")):
        with pytest.raises(ValueError, match=needle):
            slam.add_scan(points, pose)
        assert len(slam) == 1 and slam.poses.shape == (1, 4, 4)
    step = np.eye(4)
    step[0, 3] = 1.0
    report = slam.add_scan(np.zeros((0, 3)), step)  # a scan without points is still a node
    assert report["node"] == 1 and len(slam) == 2
    slam.finish()
    assert np.allclose(slam.poses[1], step)
