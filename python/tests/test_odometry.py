"""metricmap.LidarOdometry against `metricmap odometry` on the bundled KITTI scans."""

import subprocess

import numpy as np
import pytest

import metricmap as mm

FRAMES = [f"{i:06d}.bin" for i in range(4)]


def test_poses_equal_the_cli(cli, data, tmp_path):
    velodyne = data / "kitti_odometry_00/sequences/00/velodyne"
    folder = tmp_path / "scans"
    folder.mkdir()
    for f in FRAMES:
        (folder / f).symlink_to(velodyne / f)
    out = tmp_path / "poses.txt"
    subprocess.run(
        [cli, "odometry", str(folder), "--profile", "kitti", "--no-deskew", "--out-poses", str(out), "--threads", "1"],
        check=True,
        capture_output=True,
    )
    ref = np.loadtxt(out).reshape(-1, 3, 4)
    odo = mm.LidarOdometry(max_range=100, min_range=3, voxel_size=1, threads=1)
    poses = [odo.register_frame(mm.read_points(str(velodyne / f))) for f in FRAMES]
    assert len(ref) == len(poses)
    for mine, theirs in zip(poses, ref):
        np.testing.assert_allclose(mine[:3], theirs, rtol=0, atol=2e-9 + 1e-9 * np.abs(theirs).max())
        np.testing.assert_array_equal(mine[3], [0, 0, 0, 1])
    np.testing.assert_array_equal(odo.poses, np.array(poses))
    # The car drives forward (x) about 0.7 m per frame on these scans.
    assert 1.8 < poses[-1][0, 3] < 2.4
    assert odo.last_result["correspondences"] > 1000


def test_profile_of_a_kitti_scan(data):
    pts = mm.read_points(str(data / "kitti_odometry_00/sequences/00/velodyne/000000.bin"))
    p = mm.sensor_profile(pts, statistics=True)
    assert 10 <= p["max_range"] <= 100 and 0.1 <= p["voxel_size"] <= 1.0
    r = np.linalg.norm(pts[:, :3].astype(np.float64), axis=1)
    assert p["median_range"] == pytest.approx(np.median(r[r > 0]), rel=1e-3)


def test_bad_scans():
    odo = mm.LidarOdometry()
    with pytest.raises(ValueError):
        odo.register_frame(np.zeros((0, 3)))
    with pytest.raises(ValueError):
        odo.register_frame(np.full((500, 3), np.nan))
    with pytest.raises(ValueError):
        odo.register_frame(np.ones((500, 3)), timestamps=np.zeros(3))
    with pytest.raises(ValueError):
        mm.LidarOdometry(voxel_size=-1)
