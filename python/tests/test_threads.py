"""Objects shared between threads serialise their own calls: 4 threads calling one object give
what the same calls give one after another (or, where order matters, a consistent object:
every call counted, nothing lost); a call into an object from within its own call is refused."""

import threading

import numpy as np
import pytest

import metricmap as mm

THREADS = 4
INTEL = ("radish_clf_raw", "intel.clf.bz2")


def run_threads(work):
    barrier = threading.Barrier(THREADS)
    errors = []

    def body(t):
        barrier.wait()
        try:
            work(t)
        except BaseException as e:  # noqa: BLE001 - reported below
            errors.append(e)

    threads = [threading.Thread(target=body, args=(t,)) for t in range(THREADS)]
    for th in threads:
        th.start()
    for th in threads:
        th.join()
    assert not errors, errors


def scans_of(t, count=6):
    """Thread t's scans: points within 3 m of its own origin (10 t, 0, 0), apart from the others."""
    rng = np.random.default_rng(t)
    origin = np.array([10.0 * t, 0.0, 0.0])
    return origin, [origin + rng.uniform(-3, 3, (3000, 3)) for _ in range(count)]


def test_log_odds_map_from_four_threads():
    shared = mm.LogOddsMap(resolution=0.2)

    def work(t):
        origin, scans = scans_of(t)
        for s in scans:
            shared.insert_point_cloud(s, origin=origin)
            shared.known_voxels  # reads meanwhile

    run_threads(work)
    alone = mm.LogOddsMap(resolution=0.2)
    for t in range(THREADS):
        origin, scans = scans_of(t)
        for s in scans:
            alone.insert_point_cloud(s, origin=origin)
    assert shared == alone and alone.known_voxels > 0


def test_height_map_from_four_threads():
    shared = mm.HeightMap(resolution=0.1, map_size=120, z_bins=[0.1, 1.0])
    pose = np.eye(4)

    def work(t):
        for s in scans_of(t % 2)[1]:
            shared.add_frame(s * 0.3, pose)

    run_threads(work)
    alone = mm.HeightMap(resolution=0.1, map_size=120, z_bins=[0.1, 1.0])
    for t in range(THREADS):
        for s in scans_of(t % 2)[1]:
            alone.add_frame(s * 0.3, pose)
    np.testing.assert_array_equal(shared.counts, alone.counts)  # counts add: no update lost
    assert shared.counts.sum() > 0


def test_lidar_odometry_from_four_threads(data):
    src = mm.open_scan_source(data / "kitti_odometry_00")
    scans = [np.array(src[k].points) for k in range(2)]
    odo = mm.LidarOdometry()

    def work(t):
        for s in scans:
            pose = odo.register_frame(s)
            assert np.isfinite(pose).all()

    run_threads(work)
    assert odo.poses.shape == (THREADS * len(scans), 4, 4)


def test_slam2d_from_four_threads(data):
    src = mm.open_scan_source(data.joinpath(*INTEL))
    lasers = [src[k].laser for k in range(10)]
    slam = mm.Slam2D()

    def work(t):
        for angles, ranges in lasers:
            slam.add_scan(angles, ranges)
            slam.trajectory

    run_threads(work)
    slam.finish()
    assert slam.trajectory.shape == (THREADS * len(lasers), 3)
    assert np.isfinite(slam.trajectory).all()


def test_a_call_from_within_its_own_call_is_refused(data):
    src = mm.open_scan_source(data.joinpath(*INTEL))
    poses = mm.run_odometry(src, frames=range(5))["sensor_poses"]
    mapper = mm.SequenceMapper(src)

    def progress(done, total):
        mapper.occupied_cells()

    with pytest.raises(RuntimeError, match="SequenceMapper is busy in this thread"):
        mapper.build(poses, frames=range(5), progress=progress)


def test_reading_the_source_from_a_progress_callback_is_refused(data):
    src = mm.open_scan_source(data.joinpath(*INTEL))

    def progress(done, total):
        src[0]

    with pytest.raises(RuntimeError, match="ScanSource is busy in this thread"):
        mm.run_slam2d(src, frames=range(5), progress=progress)
    assert src[0].index == 0  # the source is free again


def test_a_source_shared_by_four_threads(data):
    src = mm.open_scan_source(data.joinpath(*INTEL))
    got = {}

    def work(t):
        got[t] = [src[k].laser[1].copy() for k in range(t, 40, THREADS)]

    run_threads(work)
    for t in range(THREADS):
        for k, ranges in zip(range(t, 40, THREADS), got[t]):
            np.testing.assert_array_equal(ranges, src[k].laser[1])
