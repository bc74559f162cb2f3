"""Open3D out and Open3D's cells: `origin='open3d'` bins as `voxel_down_sample`, a point origin
and the per-point cell rows as numpy's floor and `np.unique(..., return_inverse=True)`, and
`to_open3d()` gives the points Open3D reads or numpy computes."""

import sys

import numpy as np
import pytest

import metricmap as mm


@pytest.fixture(scope="module")
def cloud():
    rng = np.random.default_rng(41)
    return rng.uniform([-5.3, -2.1, 0.4], [7.9, 3.3, 2.6], size=(60000, 3)).astype(np.float32)


@pytest.mark.parametrize("voxel", [0.1, 0.25, 0.37])
def test_open3d_origin_equals_voxel_down_sample(cloud, voxel):
    o3d = pytest.importorskip("open3d")
    pcd = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(cloud.astype(np.float64)))
    theirs = np.asarray(pcd.voxel_down_sample(voxel).points)
    g = mm.grid(cloud, cell_size=voxel, origin="open3d")
    assert len(g) == len(theirs)
    a, b = np.asarray(g.means), theirs
    np.testing.assert_allclose(a[np.lexsort(a.T)], b[np.lexsort(b.T)], rtol=0, atol=1e-12)
    start = cloud.astype(np.float64).min(axis=0) - voxel * 0.5
    np.testing.assert_array_equal(g.origin, start)
    assert g.cell_size == voxel
    # the cells are Open3D's: floor((p - (min - V/2)) / V) per point, as numpy computes it
    keys = np.floor((cloud.astype(np.float64) - start) / voxel).astype(np.int64)
    assert len(np.unique(keys, axis=0)) == len(g)


def test_point_origin_and_point_cells_equal_numpy(cloud):
    origin = (0.05, -1.3, 0.71)
    g = mm.grid(cloud, cell_size=0.3, origin=origin, point_cells=True)
    keys = np.floor((cloud.astype(np.float64) - np.array(origin)) / 0.3).astype(np.int64)
    cells, inverse, counts = np.unique(keys, axis=0, return_inverse=True, return_counts=True)
    inverse = inverse.reshape(-1)
    rows = g.point_cells
    assert rows.dtype == np.int64 and rows.shape == (len(cloud),)
    # each point's cell is numpy's key of that point, and the partitions are the same
    np.testing.assert_array_equal(g.indices[rows], keys)
    assert len(g) == len(cells)
    order = np.lexsort(np.asarray(g.indices).T[::-1])  # numpy's order: x, then y, then z
    np.testing.assert_array_equal(np.asarray(g.indices)[order], cells)
    np.testing.assert_array_equal(np.asarray(g.counts)[order], counts)
    np.testing.assert_array_equal(np.argsort(order)[rows], inverse)
    # a label averaged per cell, both ways
    labels = np.arange(len(cloud)) % 7
    mine = np.bincount(rows, weights=labels) / np.asarray(g.counts)
    ref = np.bincount(inverse, weights=labels) / counts
    np.testing.assert_allclose(mine[order], ref, rtol=1e-12)
    assert g.origin == origin


def test_point_cells_of_skipped_points_and_default_none():
    pts = np.array([[0.1, 0.1, 0.1], [np.nan, 0, 0], [1.5, 0.1, 0.1], [0.2, 0.3, 0.4]], np.float32)
    g = mm.grid(pts, 1.0, point_cells=True)
    np.testing.assert_array_equal(g.point_cells, [0, -1, 1, 0])
    assert mm.grid(pts, 1.0).point_cells is None
    for origin in ("cloud-min", "world", "open3d", (0, 0, 0)):
        h = mm.grid(pts, 0.5, origin=origin, point_cells=True)
        np.testing.assert_array_equal(np.bincount(h.point_cells[h.point_cells >= 0]), h.counts)


def test_bad_origins():
    pts = np.zeros((3, 3), np.float32)
    with pytest.raises(ValueError, match=r"'cloud-min', 'world', 'open3d' or a point.*'center'"):
        mm.grid(pts, origin="center")
    with pytest.raises(ValueError, match="2 numbers"):
        mm.grid(pts, origin=(1, 2))
    with pytest.raises(ValueError, match="origin must be finite"):
        mm.grid(pts, origin=(0, np.nan, 0))
    with pytest.raises(TypeError, match="origin must be .* got dict"):
        mm.grid(pts, origin={})


def test_grid_with_point_cells_pickles(cloud):
    import pickle

    g = mm.grid(cloud, 0.5, origin="open3d", point_cells=True)
    h = pickle.loads(pickle.dumps(g))
    assert h == g
    np.testing.assert_array_equal(h.point_cells, g.point_cells)
    assert h != mm.grid(cloud, 0.5, origin="open3d")


def test_to_open3d_of_a_read_cloud_equals_open3d_reading_it(data):
    o3d = pytest.importorskip("open3d")
    path = data / "pcl_test_pcd" / "bunny.pcd"
    pcd = mm.to_open3d(mm.read_points(path))
    assert isinstance(pcd, o3d.geometry.PointCloud)
    theirs = np.asarray(o3d.io.read_point_cloud(str(path)).points)
    # the file's decimals: Open3D parses them to float64, metricmap to float32 (its precision)
    np.testing.assert_array_equal(np.asarray(pcd.points), theirs.astype(np.float32).astype(np.float64))


def test_to_open3d_of_grid_scan_and_log_odds_map(data, cloud):
    o3d = pytest.importorskip("open3d")
    g = mm.grid(cloud, 0.2, origin="open3d")
    np.testing.assert_array_equal(np.asarray(g.to_open3d().points), g.means)
    np.testing.assert_array_equal(np.asarray(mm.to_open3d(g).points), g.means)
    scan = mm.open_scan_source(data / "kitti_odometry_00")[0]
    np.testing.assert_array_equal(np.asarray(scan.to_open3d().points), scan.points.astype(np.float64))
    m = mm.LogOddsMap(0.2)
    m.insert_point_cloud(cloud[:5000], origin=(0.0, 0.0, 1.0))
    keys, log_odds = m.voxels()
    centres = (keys + 0.5) * 0.2  # voxel k spans [k r, (k + 1) r)
    for free, chosen in ((False, log_odds > 0), (True, log_odds <= 0)):
        got = np.asarray(m.to_open3d(free=free).points)
        want = centres[chosen]
        assert len(got) == len(want) > 0
        np.testing.assert_allclose(got[np.lexsort(got.T)], want[np.lexsort(want.T)], atol=1e-9)
    assert isinstance(m.to_open3d(), o3d.geometry.PointCloud)


def test_to_open3d_without_open3d_says_what_to_install(monkeypatch):
    monkeypatch.setitem(sys.modules, "open3d", None)  # `import open3d` now raises ImportError
    with pytest.raises(ImportError, match=r"to_open3d needs Open3D.*pip install open3d"):
        mm.to_open3d(np.zeros((2, 3)))
    with pytest.raises(ImportError, match="needs Open3D"):
        mm.grid(np.zeros((2, 3)), 1.0).to_open3d()


def test_to_open3d_refuses_what_is_not_points():
    pytest.importorskip("open3d")
    with pytest.raises(ValueError, match=r"\(N, 3\) or \(N, 4\).*shape \(3,\)"):
        mm.to_open3d(np.zeros(3))
