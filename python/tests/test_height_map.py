"""metricmap.HeightMap and fit_floor against `metricmap heightmap` on the bundled TUM frame."""

import json
import subprocess

import numpy as np
import pytest

import metricmap as mm

DEPTH = "open3d_tum_depth/TUM_depth.png"
CAMERA = "open3d_tum_depth/camera_primesense.json"


def test_equals_the_cli(cli, data, tmp_path):
    out = subprocess.run(
        [cli, "heightmap", str(data / DEPTH), "--camera", str(data / CAMERA), "--auto-floor",
         "--resolution", "0.05", "--map-size", "200", "--z-bins", "0.1,1.0",
         "--out-prefix", str(tmp_path / "tum"), "--format", "json"],
        check=True, capture_output=True, text=True,
    ).stdout
    ref = json.loads(out)
    k = mm.read_camera(str(data / CAMERA))
    cloud = mm.depth_to_cloud(mm.read_depth_image(str(data / DEPTH)), k["fx"], k["fy"], k["cx"], k["cy"], 0.0002)
    points = cloud.reshape(-1, 3)
    to_map, plane, inliers = mm.fit_floor(points)
    np.testing.assert_allclose(plane, ref["floor"]["plane"], rtol=0, atol=1e-12)
    assert inliers == ref["floor"]["inliers"]
    hm = mm.HeightMap(resolution=0.05, map_size=200, z_bins=[0.1, 1.0])
    hm.add_frame(points, to_map)
    s = hm.statistics
    assert s["bin_counts"] == ref["bin_counts"]
    assert (s["points_outside_map"], s["obstacle_cells"], s["explored_cells"]) == (
        ref["points_outside_map"], ref["obstacle_cells"], ref["explored_cells"])
    np.testing.assert_array_equal(hm.counts, np.load(tmp_path / "tum_counts.npy").reshape(hm.counts.shape))
    assert hm.obstacles.sum() == ref["obstacle_cells"]


def test_counts_by_numpy():
    # Cell (col, row) covers x in [(col - N/2) r, ...), y in [(N/2 - 1 - row) r, ...); z bins
    # np.digitize(z, z_bins).
    rng = np.random.default_rng(3)
    pts = rng.uniform(-1.2, 1.2, size=(5000, 3)).astype(np.float32).astype(np.float64)
    hm = mm.HeightMap(resolution=0.1, map_size=20, z_bins=[-0.5, 0.0, 0.5])
    hm.add_frame(pts, np.eye(4))
    hm.add_frame(pts, np.eye(4))
    col = np.floor(pts[:, 0] / 0.1).astype(int) + 10
    row = 10 - 1 - np.floor(pts[:, 1] / 0.1).astype(int)
    z = np.digitize(pts[:, 2], [-0.5, 0.0, 0.5])
    inside = (col >= 0) & (col < 20) & (row >= 0) & (row < 20)
    ref = np.zeros((20, 20, 4), np.uint32)
    np.add.at(ref, (row[inside], col[inside], z[inside]), 2)
    np.testing.assert_array_equal(hm.counts, ref)
    assert hm.statistics["frames"] == 2 and hm.statistics["points_outside_map"] == 2 * (~inside).sum()


def test_camera_to_map_and_bad_parameters():
    t = mm.camera_to_map(1.0, 0.0)
    np.testing.assert_allclose(t @ [0, 0, 1, 1], [0, 1, 1, 1], atol=1e-12)  # optical axis -> forward
    with pytest.raises(ValueError):
        mm.HeightMap(resolution=0.0)
    with pytest.raises(ValueError):
        mm.HeightMap(z_bins=[1.0, 0.5])
    with pytest.raises(ValueError):
        mm.HeightMap().add_frame(np.zeros((3, 3)), np.ones((4, 4)))
