"""Scan sources, odometry runs and sequence maps from Python against independent oracles: the
files themselves read with numpy (KITTI .bin, .npy, times.txt, calib.txt, poses/00.txt, the
CARMEN log's text), and the `metricmap odometry` / `metricmap map` commands on the same data."""

import bz2
import json
import math
import pathlib
import shutil
import subprocess

import numpy as np
import pytest

import metricmap as mm

KITTI = "kitti_odometry_00"


def kitti_dir(data):
    return data / KITTI / "sequences" / "00"


def read_kitti_rows(path):
    rows = np.loadtxt(path, ndmin=2)
    out = np.tile(np.eye(4), (len(rows), 1, 1))
    out[:, :3, :4] = rows.reshape(-1, 3, 4)
    return out


def kitti_tr(data):
    for line in (kitti_dir(data) / "calib.txt").read_text().splitlines():
        if line.startswith("Tr:"):
            t = np.eye(4)
            t[:3, :4] = np.array(line.split()[1:], dtype=float).reshape(3, 4)
            return t
    raise AssertionError("no Tr in calib.txt")


def test_kitti_scans_equal_the_bin_files(data):
    src = mm.open_scan_source(data / KITTI)
    bins = sorted((kitti_dir(data) / "velodyne").glob("*.bin"))
    assert len(src) == len(bins) > 0
    for i, path in enumerate(bins):
        raw = np.fromfile(path, dtype=np.float32).reshape(-1, 4)
        scan = src[i]
        assert scan.index == i
        assert pathlib.Path(scan.name).name == path.name
        assert scan.points.shape == (len(raw), 3) and scan.points.dtype == np.float32
        np.testing.assert_array_equal(scan.points, raw[:, :3])
        np.testing.assert_array_equal(scan.intensity, raw[:, 3])
    times = np.loadtxt(kitti_dir(data) / "times.txt")[: len(bins)]
    np.testing.assert_array_equal(src.info["stamps"], times)
    assert [s.stamp for s in src] == list(times)  # iteration by the sequence protocol
    assert src[-1].index == len(bins) - 1


def test_kitti_info_reference_is_the_velodyne_poses(data):
    src = mm.open_scan_source(data / KITTI)
    info = src.info
    tr = kitti_tr(data)
    np.testing.assert_allclose(info["sensor_to_base"], tr, atol=1e-12)
    cam = read_kitti_rows(data / KITTI / "poses" / "00.txt")[: len(src)]
    velo = np.linalg.inv(tr) @ cam @ tr  # Tr^-1 P Tr
    assert info["kind"] == "kitti" and info["planar"] is False
    np.testing.assert_allclose(info["reference_poses"], velo, atol=1e-9)
    # the map world of `metricmap kitti`: camera 0 of the first frame, P Tr
    np.testing.assert_allclose(mm.reference_sensor_poses(src), cam @ tr, atol=1e-9)


def test_scan_views_keep_the_scan_alive(data):
    src = mm.open_scan_source(data / KITTI)
    pts = src[0].points  # the Scan object is gone, its view remains valid
    raw = np.fromfile(kitti_dir(data) / "velodyne" / "000000.bin", dtype=np.float32)
    np.testing.assert_array_equal(pts, raw.reshape(-1, 4)[:, :3])
    assert not pts.flags.writeable


def test_folder_of_npy_scans_with_stamps_and_poses(tmp_path, data):
    rng = np.random.default_rng(3)
    clouds = [rng.normal(size=(200 + 10 * k, 3)).astype(np.float32) for k in range(3)]
    for k, c in enumerate(clouds):
        np.save(tmp_path / f"scan_{k}.npy", c)
    (tmp_path / "times.txt").write_text("0.5\n1.5\n2.5\n")
    poses = np.tile(np.eye(4), (3, 1, 1))
    poses[:, 0, 3] = [0.0, 1.0, 2.5]
    (tmp_path / "poses.txt").write_text(
        "".join(" ".join(f"{v:.9e}" for v in p[:3].ravel()) + "\n" for p in poses)
    )
    src = mm.open_scan_source(tmp_path)
    assert src.info["kind"] == "folder" and len(src) == 3
    for k, c in enumerate(clouds):
        np.testing.assert_array_equal(src[k].points, c)
        assert src[k].stamp == [0.5, 1.5, 2.5][k]
        assert src[k].laser is None and src[k].odometry is None
    np.testing.assert_allclose(src.info["reference_poses"], poses, atol=1e-9)


def carmen_flaser(path, count):
    """The first `count` FLASER messages of a CARMEN log, parsed here from its text."""
    out = []
    with bz2.open(path, "rt") as f:
        for line in f:
            tok = line.split()
            if not tok or tok[0] != "FLASER":
                continue
            n = int(tok[1])
            r = np.array(tok[2 : 2 + n], dtype=float)
            rest = tok[2 + n :]
            odom = [float(v) for v in rest[3:6]]
            out.append((r, odom, float(rest[6])))
            if len(out) == count:
                return out
    return out


def test_carmen_scans_equal_the_log_text(data):
    path = data / "radish_clf_raw" / "intel.clf.bz2"
    expected = carmen_flaser(path, 40)
    src = mm.open_scan_source(path)
    assert src.info["kind"] == "carmen" and src.info["planar"] is True
    for k, (r, odom, stamp) in enumerate(expected):
        scan = src[k]
        angles, ranges = scan.laser
        n = len(r)
        step = math.pi / (n - 1) if n % 2 else math.pi / n  # carmen_log.h's FLASER rule
        np.testing.assert_allclose(angles, -math.pi / 2 + step * np.arange(n), atol=1e-12)
        valid = (r > 0) & (r <= 1e4)
        np.testing.assert_array_equal(ranges[valid], r[valid])
        assert np.isnan(ranges[~valid]).all()
        assert scan.stamp == stamp
        c, s = math.cos(odom[2]), math.sin(odom[2])
        expect_odom = np.array([[c, -s, 0, odom[0]], [s, c, 0, odom[1]], [0, 0, 1, 0], [0, 0, 0, 1]])
        np.testing.assert_allclose(scan.odometry, expect_odom, atol=1e-12)
        xy = np.stack([ranges * np.cos(angles), ranges * np.sin(angles)], axis=1)
        pts = scan.points
        np.testing.assert_allclose(pts[valid, :2], xy[valid], rtol=1e-6, atol=1e-6)
        assert (pts[valid, 2] == 0).all()


def cli_json(cli, *args):
    out = subprocess.run([cli, *map(str, args), "--format", "json"], capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    return json.loads(out.stdout)


def test_odometry_equals_the_cli_on_kitti(cli, data, tmp_path):
    poses_file = tmp_path / "odo.txt"
    report = cli_json(cli, "odometry", data / KITTI, "--out-poses", poses_file)
    expected = read_kitti_rows(poses_file)
    run = mm.run_odometry(data / KITTI)
    assert run["poses"].shape == (len(expected), 4, 4)
    np.testing.assert_allclose(run["poses"], expected, rtol=0, atol=1e-7)  # rows are %.9e
    assert run["convention"] == report["convention"] == "kitti camera 0"
    np.testing.assert_array_equal(run["stamps"], np.loadtxt(kitti_dir(data) / "times.txt")[: len(expected)])
    # per-frame RPE against poses/00.txt: recomputed here from the two trajectories
    ref = read_kitti_rows(data / KITTI / "poses" / "00.txt")[: len(expected)]
    np.testing.assert_allclose(run["reference_poses"], ref, atol=1e-9)
    err = [
        np.linalg.inv(np.linalg.inv(ref[k - 1]) @ ref[k]) @ (np.linalg.inv(run["poses"][k - 1]) @ run["poses"][k])
        for k in range(1, len(ref))
    ]
    np.testing.assert_allclose(run["rpe"]["translation"], [np.linalg.norm(e[:3, 3]) for e in err], atol=1e-6)


def test_odometry_on_a_folder_with_frames_equals_the_cli(cli, data, tmp_path):
    folder = tmp_path / "scans"
    folder.mkdir()
    for p in sorted((kitti_dir(data) / "velodyne").glob("*.bin"))[:4]:
        shutil.copy(p, folder / p.name)
    poses_file = tmp_path / "odo_tum.txt"
    cli_json(cli, "odometry", folder, "--frames", "0-2", "--out-poses", poses_file, "--pose-format", "tum")
    rows = np.loadtxt(poses_file, ndmin=2)
    src = mm.open_scan_source(folder)
    run = mm.run_odometry(src, frames=[0, 1, 2], threads=1)
    assert list(run["frames"]) == [0, 1, 2]
    np.testing.assert_allclose(run["poses"][:, :3, 3], rows[:, 1:4], atol=1e-7)
    assert run["convention"] == "sensor"
    np.testing.assert_array_equal(run["poses"][0], np.eye(4))


def test_sequence_map_equals_the_cli_map(cli, data, tmp_path):
    out = tmp_path / "m.pgm"
    cli_json(cli, "map", data / KITTI, "--poses", "reference", "--out-map", out, "--map-resolution", "0.2")
    src = mm.open_scan_source(data / KITTI)
    mapper = mm.SequenceMapper(src, map_resolution=0.2)
    mapper.build(mm.reference_sensor_poses(src))
    mine = tmp_path / "mine.pgm"
    mapper.write_map(mine)
    assert mine.read_bytes() == out.read_bytes()
    assert mine.with_suffix(".yaml").read_text().replace("mine.pgm", "m.pgm") == out.with_suffix(
        ".yaml"
    ).read_text()
    hits = mapper.hit_map()["hits"]
    pgm = np.frombuffer(out.read_bytes()[-hits.size :], dtype=np.uint8).reshape(hits.shape)
    np.testing.assert_array_equal(pgm == 0, hits >= 1)  # occupied (black) where hit
    assert mapper.occupied_cells() == int((hits >= 1).sum())
    # a second build with other poses rebuilds; the first pose alone gives a subset of the cells
    mapper.build(mm.reference_sensor_poses(src, [0]), frames=[0])
    assert 0 < mapper.occupied_cells() < int((hits >= 1).sum())


def test_sequence_occupancy_2d_equals_the_cli_on_a_carmen_log(cli, data, tmp_path):
    log = data / "radish_clf_raw" / "intel.clf.bz2"
    out = tmp_path / "grid.pgm"
    cli_json(cli, "map", log, "--frames", "0-49", "--poses", "odometry", "--out-occupancy-2d", out,
             "--occupancy-2d-resolution", "0.1")
    src = mm.open_scan_source(log)
    run = mm.run_odometry(src, frames=range(50))
    mapper = mm.SequenceMapper(src, occupancy_2d_resolution=0.1)
    mapper.build(run["sensor_poses"], frames=range(50))
    mine = tmp_path / "mine.pgm"
    mapper.write_map(mine, kind="occupancy_2d")
    assert mine.read_bytes() == out.read_bytes()
    g = mapper.occupancy_2d()
    assert g["known_cells"] == np.count_nonzero(~np.isnan(g["log_odds"])) > 0


def test_global_cloud_equals_the_scans_moved_by_numpy(data):
    src = mm.open_scan_source(data / KITTI)
    poses = mm.reference_sensor_poses(src, [0, 2])
    mapper = mm.SequenceMapper(src, keep_global_cloud=True, min_range=2.5, max_range=40.0)
    cloud = mapper.build(poses, frames=[0, 2]).global_cloud()
    expected = []
    for pose, k in zip(poses, [0, 2]):
        p = np.fromfile(kitti_dir(data) / "velodyne" / f"{k:06d}.bin", np.float32).reshape(-1, 4)[:, :3]
        r = np.linalg.norm(p.astype(np.float64), axis=1)
        p = p[(r >= 2.5) & (r <= 40.0)]
        expected.append(p.astype(np.float64) @ pose[:3, :3].T + pose[:3, 3])
    expected = np.concatenate(expected)
    assert cloud.shape == expected.shape
    np.testing.assert_allclose(cloud, expected, atol=2e-4)  # float32 transforms of ~40 m
