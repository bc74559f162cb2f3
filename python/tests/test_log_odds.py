"""metricmap.LogOddsMap against OctoMap's sensor model worked by hand and against the CLI."""

import math
import subprocess

import numpy as np
import pytest

import metricmap as mm


def logodds(p):
    return np.float32(math.log(p / (1 - p)))


def test_one_beam_by_hand():
    # A beam along x from the centre of voxel (0,0,0) to voxel (10,0,0) at 0.1 m: voxels 0..9
    # are misses, voxel 10 the hit (OctoMap's insertPointCloud).
    m = mm.LogOddsMap(resolution=0.1)
    r = m.insert_point_cloud(np.array([[1.05, 0.05, 0.05]], np.float32), [0.05, 0.05, 0.05])
    assert (r["beams"], r["hit_voxels"], r["miss_voxels"]) == (1, 1, 10)
    keys, values = m.voxels()
    order = np.argsort(keys[:, 0])
    np.testing.assert_array_equal(keys[order], [[i, 0, 0] for i in range(11)])
    expected = [logodds(0.4)] * 10 + [logodds(0.7)]
    np.testing.assert_array_equal(values[order], np.array(expected, np.float32))
    occ, free = m.extract_point_cloud()
    np.testing.assert_allclose(occ, [[1.05, 0.05, 0.05]])
    assert len(free) == 10
    centres = np.column_stack([np.arange(11) * 0.1 + 0.05, np.full(11, 0.05), np.full(11, 0.05)])
    np.testing.assert_array_equal(m.states(centres), [mm.FREE] * 10 + [mm.OCCUPIED])
    np.testing.assert_allclose(m.probability(centres)[-1], 0.7, rtol=1e-6)
    assert m.probability([5.0, 5.0, 5.0])[0] == 0.5 and np.isnan(m.log_odds([5.0, 5.0, 5.0])[0])
    # clamping: 20 hits saturate at clamp_max
    for _ in range(20):
        m.insert_point_cloud(np.array([[1.05, 0.05, 0.05]]), [0.05, 0.05, 0.05])
    assert m.log_odds([1.05, 0.05, 0.05])[0] == logodds(0.971)


def test_max_range_cuts_beams():
    m = mm.LogOddsMap(resolution=0.1)
    r = m.insert_point_cloud(np.array([[2.05, 0.05, 0.05]]), [0.05, 0.05, 0.05], max_range=1.0)
    assert r["beams_cut"] == 1 and r["hit_voxels"] == 0
    assert m.occupied_voxels == 0 and m.free_voxels == 10
    # the map keeps its voxels when a later call changes max_range
    m.insert_point_cloud(np.array([[0.05, 0.55, 0.05]]), [0.05, 0.05, 0.05])
    assert m.free_voxels == 10 + 4 and m.occupied_voxels == 1


def test_file_round_trip(tmp_path, data):
    pts = mm.read_points(str(data / "kitti_odometry_00/sequences/00/velodyne/000000.bin"))[::20]
    m = mm.LogOddsMap(resolution=0.25)
    m.insert_point_cloud(pts, [0, 0, 0], max_range=30)
    m.write(str(tmp_path / "m.ot"))
    back = mm.LogOddsMap.read(str(tmp_path / "m.ot"))
    k1, v1 = m.voxels()
    k2, v2 = back.voxels()
    a, b = np.lexsort(k1.T), np.lexsort(k2.T)
    np.testing.assert_array_equal(k1[a], k2[b])
    np.testing.assert_array_equal(v1[a], v2[b])
    m.write(str(tmp_path / "m.bt"))
    bt = mm.LogOddsMap.read(str(tmp_path / "m.bt"))
    assert bt.occupied_voxels == m.occupied_voxels


def test_equals_the_cli(cli, data, tmp_path):
    # The CLI casts a PCD from its VIEWPOINT (identity here): the same beams as from the origin.
    pts = mm.read_points(str(data / "kitti_odometry_00/sequences/00/velodyne/000003.bin"))[::4]
    pcd = tmp_path / "scan.pcd"
    mm.write_pcd(str(pcd), pts)
    ot = tmp_path / "cli.ot"
    pgm = tmp_path / "band.pgm"
    subprocess.run(
        [cli, "occupancy", str(pcd), "--resolution", "0.2", "--max-range", "25", "--out-ot", str(ot),
         "--out-map", str(pgm), "--band=-1.5,0.5"],
        check=True,
        capture_output=True,
    )
    m = mm.LogOddsMap(resolution=0.2)
    m.insert_point_cloud(mm.read_points(str(pcd)), [0, 0, 0], max_range=25)
    ref = mm.LogOddsMap.read(str(ot))
    k1, v1 = m.voxels()
    k2, v2 = ref.voxels()
    a, b = np.lexsort(k1.T), np.lexsort(k2.T)
    np.testing.assert_array_equal(k1[a], k2[b])
    np.testing.assert_array_equal(v1[a], v2[b])
    # the trinary map of a height band, as map_server's PGM + YAML
    cells, info = m.project_band(-1.5, 0.5)
    raw = pgm.read_bytes()
    header = [t for line in raw.split(b"\n")[:4] if not line.startswith(b"#") for t in line.split()][:4]
    assert header[0] == b"P5" and (int(header[2]), int(header[1])) == cells.shape
    np.testing.assert_array_equal(np.frombuffer(raw[-cells.size :], np.uint8).reshape(cells.shape), cells)
    yaml = dict(line.split(": ", 1) for line in pgm.with_suffix(".yaml").read_text().splitlines())
    assert float(yaml["resolution"]) == info["resolution"]
    ox, oy, _ = (float(v) for v in yaml["origin"].strip("[]").split(","))
    assert (ox, oy) == pytest.approx(info["origin"], abs=1e-9)
    assert info["occupied"] == (cells == 0).sum() > 0 and info["free"] == (cells == 254).sum() > 0


def test_reads_the_bundled_octomap(data):
    m = mm.LogOddsMap.read(str(data / "octomap_geb079/geb079.bt"))
    assert m.occupied_voxels > 0 and m.resolution > 0
    occ, free = m.extract_point_cloud()
    assert len(occ) == m.occupied_voxels and len(free) == m.free_voxels
    assert (m.states(occ) == mm.OCCUPIED).all()


def test_bad_files(tmp_path):
    with pytest.raises(OSError):
        mm.LogOddsMap.read(str(tmp_path / "missing.bt"))
    bad = tmp_path / "bad.bt"
    bad.write_bytes(b"# Octomap OcTree binary file\nnonsense\n")
    with pytest.raises(OSError):
        mm.LogOddsMap.read(str(bad))
    with pytest.raises(ValueError):
        mm.LogOddsMap().write(str(tmp_path / "m.xyz"))
    with pytest.raises(OSError):
        mm.LogOddsMap().write(str(tmp_path / "no/such/dir/m.bt"))
