"""Objects with `.points` (Open3D's PointCloud, duck-typed; a Scan) are taken wherever points
are: the results equal those of the same points as an array. An object array is refused with a
message that says what to give instead."""

import numpy as np
import pytest

import metricmap as mm


class Cloud:
    """A stand-in with nothing but `.points`."""

    def __init__(self, points):
        self.points = points


@pytest.fixture(scope="module")
def bunny(data):
    return mm.read_points(data / "pcl_test_pcd" / "bunny.pcd")[:, :3].astype(np.float64)


def test_duck_typed_points_everywhere(bunny):
    duck = Cloud(bunny)
    assert mm.grid(duck, cell_size=0.01) == mm.grid(bunny, cell_size=0.01)
    a, b = mm.octree(duck, max_points=50, min_cell_size=0.005), mm.octree(bunny, max_points=50, min_cell_size=0.005)
    np.testing.assert_array_equal(a.depths, b.depths)
    m1, m2 = mm.LogOddsMap(0.02), mm.LogOddsMap(0.02)
    m1.insert_point_cloud(duck, origin=(0, 0, 0.3))
    m2.insert_point_cloud(bunny, origin=(0, 0, 0.3))
    assert m1 == m2
    np.testing.assert_array_equal(m1.probability(duck), m2.probability(bunny))
    assert mm.sensor_profile(duck) == mm.sensor_profile(bunny)


def test_open3d_point_cloud(bunny):
    o3d = pytest.importorskip("open3d")
    pcd = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(bunny))
    assert mm.grid(pcd, cell_size=0.01) == mm.grid(np.asarray(pcd.points), cell_size=0.01)
    # the counts per cell agree with Open3D's own voxel binning of the same points
    g = mm.grid(pcd, cell_size=0.01, origin="world")
    keys = np.floor(bunny / 0.01).astype(np.int64)
    assert len(g) == len(np.unique(keys, axis=0))


def test_a_scan_is_points(data):
    src = mm.open_scan_source(data / "kitti_odometry_00")
    scan = src[0]
    assert mm.grid(scan, cell_size=1.0) == mm.grid(np.array(scan.points), cell_size=1.0)


def test_object_dtype_says_what_to_give():
    ragged = np.array([np.zeros(3), np.zeros(2)], dtype=object)
    with pytest.raises(TypeError, match=r"dtype object \(rows of different lengths.*\.points"):
        mm.grid(ragged)
    with pytest.raises(TypeError, match="dtype object"):
        mm.grid(Cloud(ragged))
