"""metricmap.grid against the study's published table, numpy and Open3D."""

import numpy as np
import pytest

import metricmap as mm

# The study's table (README, first configuration: cell 1.0): total, occupied, empty, mean.
STUDY_GRID = {
    "ciencias000": (79120, 2477, 76643, 23.75),
    "museo000": (3360, 338, 3022, 234.17),
    "poli000": (45630, 1625, 44005, 38.66),
    "poli001": (48960, 1654, 47306, 37.14),
}


@pytest.mark.parametrize("name", sorted(STUDY_GRID))
def test_study_table(data, name):
    points = mm.read_points(str(data / "ua_mapas_metricos_pcd" / f"{name}.pcd"))
    s = mm.grid(points, cell_size=1.0).statistics
    total, occupied, empty, mean = STUDY_GRID[name]
    assert (s["total_cells"], s["occupied_cells"], s["empty_cells"]) == (total, occupied, empty)
    assert round(s["mean_points_per_occupied_cell"], 2) == mean
    assert s["points"] == len(points)


def numpy_grid(points, cell):
    """World-aligned cells as pcl::VoxelGrid: floor(p * (1 / cell)) in float32."""
    p32 = np.ascontiguousarray(points[:, :3], dtype=np.float32)
    idx = np.floor(p32 * np.float32(1.0 / cell)).astype(np.int64)
    keys, inverse, counts = np.unique(idx, axis=0, return_inverse=True, return_counts=True)
    sums = np.zeros((len(keys), 3))
    np.add.at(sums, inverse.ravel(), p32.astype(np.float64))
    return keys, counts, sums / counts[:, None]


def sort_zyx(keys):
    return np.lexsort((keys[:, 0], keys[:, 1], keys[:, 2]))


@pytest.mark.parametrize("cell", [1.0, 0.5, 0.3])
@pytest.mark.parametrize(
    "path", ["ua_mapas_metricos_pcd/museo000.pcd", "kitti_odometry_00/sequences/00/velodyne/000000.bin"]
)
def test_world_cells_equal_numpy(data, path, cell):
    points = mm.read_points(str(data / path))
    g = mm.grid(points, cell_size=cell, origin="world")
    keys, counts, means = numpy_grid(points, cell)
    order = sort_zyx(keys)  # the library's order: x fastest, then y, then z
    np.testing.assert_array_equal(g.indices, keys[order])
    np.testing.assert_array_equal(g.counts, counts[order])
    np.testing.assert_allclose(g.means, means[order], rtol=0, atol=1e-9)
    s = g.statistics
    dims = keys.max(axis=0) - keys.min(axis=0) + 1
    assert s["occupied_cells"] == len(keys)
    assert s["total_cells"] == int(np.prod(dims))
    assert s["empty_cells"] == s["total_cells"] - len(keys)
    assert s["mean_points_per_occupied_cell"] == pytest.approx(len(points) / len(keys), rel=1e-12)
    assert g.min_index == tuple(keys.min(axis=0))


def test_cloud_min_cells_equal_numpy_on_kitti(data):
    # floor((p - min) / cell) in double, on the points that are not within 1e-4 cells of a
    # boundary (the library snaps coordinates within float32 rounding of one onto it).
    points = mm.read_points(str(data / "kitti_odometry_00/sequences/00/velodyne/000001.bin"))
    p = points[:, :3].astype(np.float64)
    q = (p - p.min(axis=0)) / 0.5
    keep = (np.abs(q - np.round(q)) > 1e-4).all(axis=1)
    keep[np.argmin(p, axis=0)] = True  # the rows that define the minimum stay
    assert keep.mean() > 0.99
    points, p = points[keep], p[keep]
    idx = np.floor((p - p.min(axis=0)) / 0.5).astype(np.int64)
    keys, counts = np.unique(idx, axis=0, return_counts=True)
    g = mm.grid(points, cell_size=0.5)
    order = sort_zyx(keys)
    np.testing.assert_array_equal(g.indices, keys[order])
    np.testing.assert_array_equal(g.counts, counts[order])
    assert g.statistics["total_cells"] == int(np.prod(idx.max(axis=0) + 1))


@pytest.mark.parametrize("cell", [1.0, 0.5])
def test_means_equal_open3d_voxel_down_sample(data, cell):
    o3d = pytest.importorskip("open3d")
    points = mm.read_points(str(data / "kitti_odometry_00/sequences/00/velodyne/000002.bin"))
    p = points[:, :3].astype(np.float64)
    pcd = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(p))
    # Bounds on multiples of the cell: Open3D's cells floor((p - min_bound) / cell) are then the
    # world-aligned cells floor(p / cell), exactly (cell a power of two).
    lo = (np.floor(p.min(axis=0) / cell) - 1) * cell
    hi = (np.floor(p.max(axis=0) / cell) + 2) * cell
    down, _, traced = pcd.voxel_down_sample_and_trace(cell, lo, hi, False)
    o3d_means = np.asarray(down.points)
    o3d_counts = np.array([len(ix) for ix in traced])
    g = mm.grid(points, cell_size=cell, origin="world")
    assert len(g) == len(o3d_means)
    mine = np.lexsort(g.means.T)
    theirs = np.lexsort(o3d_means.T)
    np.testing.assert_allclose(g.means[mine], o3d_means[theirs], rtol=0, atol=1e-9)
    np.testing.assert_array_equal(g.counts[mine], o3d_counts[theirs])


def test_float64_input_gives_the_float32_result(data):
    points = mm.read_points(str(data / "ua_mapas_metricos_pcd/poli000.pcd"))
    a = mm.grid(points, 0.5)
    b = mm.grid(points[:, :3].astype(np.float64), 0.5)
    np.testing.assert_array_equal(a.indices, b.indices)
    np.testing.assert_array_equal(a.means, b.means)


def test_threads_do_not_change_the_result(data):
    points = mm.read_points(str(data / "kitti_odometry_00/sequences/00/velodyne/000000.bin"))
    a = mm.grid(points, 0.25, threads=1)
    b = mm.grid(points, 0.25, threads=2)
    np.testing.assert_array_equal(a.indices, b.indices)
    np.testing.assert_array_equal(a.means, b.means)


def test_nan_points_are_skipped_and_counted():
    pts = np.array([[0.1, 0.1, 0.1], [np.nan, 0, 0], [0.2, 0.2, np.inf], [1.5, 0.1, 0.1]], np.float32)
    s = mm.grid(pts, 1.0).statistics
    assert s["skipped_points"] == 2 and s["points"] == 2 and s["occupied_cells"] == 2


def test_compare_equals_the_cli(cli, data):
    import json
    import subprocess

    files = [str(data / "ua_mapas_metricos_pcd" / f"{n}.pcd") for n in ("museo000", "poli001")]
    ref = json.loads(subprocess.run([cli, "compare", *files, "--format", "json"], check=True,
                                    capture_output=True, text=True).stdout)
    rows = mm.compare(files)
    assert len(rows) == len(ref) == 6
    for mine, theirs in zip(rows, ref):
        assert mine["file"] == theirs["file"] and mine["points"] == theirs["points"]
        assert mine["config"] == theirs["config"]
        assert mine["grid"] == theirs["grid"]
        assert mine["octree"] == theirs["octree"]
