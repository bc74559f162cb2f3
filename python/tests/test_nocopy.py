"""Inputs read in place and results as views: measured with tracemalloc (numpy's buffers are
traced; the library's own memory is not) and by addresses."""

import gc
import tracemalloc

import numpy as np
import pytest

import metricmap as mm


@pytest.fixture(scope="module")
def kitti(data):
    return mm.read_points(str(data / "kitti_odometry_00/sequences/00/velodyne/000000.bin"))


def peak_of(fn, *args, **kwargs):
    gc.collect()
    tracemalloc.start()
    try:
        fn(*args, **kwargs)
        return tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()


def test_read_points_gives_the_kernel_layout(kitti):
    assert kitti.dtype == np.float32 and kitti.shape[1] == 4 and kitti.flags.c_contiguous
    assert len(kitti) > 100_000


@pytest.mark.parametrize("layout", ["n4", "n3", "n4_every_other_row"])
def test_float32_points_are_not_copied(kitti, layout):
    a = {
        "n4": kitti,
        "n3": np.ascontiguousarray(kitti[:, :3]),
        "n4_every_other_row": kitti[::2],
    }[layout]
    limit = a[:, :3].size * 4 // 8  # far below one float32 copy of the points
    assert peak_of(mm.grid, a, 0.5) < limit
    assert peak_of(mm.octree, a, 50, 0.5) < limit
    assert peak_of(mm.LogOddsMap(0.5).insert_point_cloud, a, [0, 0, 0], 20.0) < limit


def unaligned(a):
    raw = np.zeros(a.nbytes + 1, np.uint8)
    out = np.frombuffer(raw.data, a.dtype, count=a.size, offset=1).reshape(a.shape)
    out[:] = a
    assert not out.flags.aligned
    return out


@pytest.mark.parametrize(
    "convert",
    [lambda a: a.astype(np.float64), np.asfortranarray, lambda a: a[:, :3][::2], unaligned, lambda a: a.astype(">f4")],
    ids=["float64", "fortran", "n3_strided", "unaligned", "big_endian"],
)
def test_other_layouts_are_converted_once(kitti, convert):
    a = convert(kitti)
    copy = a.shape[0] * a.shape[1] * 4
    peak = peak_of(mm.grid, a, 0.5)
    assert copy <= peak < 3 * copy + 65536  # the float32 copy (float64: plus a check copy)
    np.testing.assert_array_equal(mm.grid(a, 0.5).means, mm.grid(np.ascontiguousarray(a, np.float32), 0.5).means)


def test_result_arrays_are_views_of_the_result(kitti):
    g = mm.grid(kitti, 0.5)
    means, indices, counts = g.means, g.indices, g.counts
    for v in (means, indices, counts):
        assert not v.flags.owndata and not v.flags.writeable
    base = indices.__array_interface__["data"][0]
    assert g.indices.__array_interface__["data"][0] == base  # the same memory on every access
    assert means.strides[0] == indices.strides[0] == counts.strides[0]  # one record per cell
    assert 0 < means.__array_interface__["data"][0] - base < means.strides[0]
    assert peak_of(getattr, g, "means") < 4096  # no copy made
    expected = means.copy()
    del g
    gc.collect()
    np.testing.assert_array_equal(means, expected)  # the view keeps the result alive


def test_octree_views_keep_the_result_alive(kitti):
    o = mm.octree(kitti, 50, 0.5)
    counts, order = o.counts, o.point_order
    n = int(counts[0])
    del o
    gc.collect()
    assert n == len(order) == len(kitti)


def test_read_points_array_owns_the_cloud(data):
    a = mm.read_points(str(data / "ua_mapas_metricos_pcd/museo000.pcd"))
    b = a[:10].copy()
    gc.collect()
    np.testing.assert_array_equal(a[:10], b)
    np.testing.assert_array_equal(a[:, 3], 1.0)
