"""metricmap.DistanceField against scipy's exact EDT (an independent implementation), its
gradient against finite differences, the field as a zero-copy view, incremental updates equal
to recomputing, and the GIL released during the transform."""

import threading
import time

import numpy as np
import pytest

import metricmap as mm

scipy_ndimage = pytest.importorskip("scipy.ndimage")


def random_log_odds_map(seed, n=4000, resolution=0.1):
    rng = np.random.default_rng(seed)
    m = mm.LogOddsMap(resolution=resolution)
    origin = np.zeros(3)
    pts = rng.uniform(-2.0, 2.0, (n, 3)).astype(np.float32)
    pts[:, 2] *= 0.3
    m.insert_point_cloud(pts, origin)
    return m


def occupancy_of(field):
    return field.states == mm.OCCUPIED


def test_points_field_equals_scipy_edt():
    rng = np.random.default_rng(1)
    pts = rng.uniform(-1.0, 1.0, (300, 3))
    f = mm.DistanceField(pts, resolution=0.05, max_distance=0.3)
    occ = occupancy_of(f)
    assert occ.sum() == len(np.unique(np.floor(pts / 0.05), axis=0))
    ref = np.minimum(scipy_ndimage.distance_transform_edt(~occ) * 0.05, 0.3)
    assert f.field.dtype == np.float32 and f.field.shape == f.shape
    assert np.abs(f.field - ref).max() < 1e-5


def test_log_odds_signed_field_equals_scipy_edt_and_is_a_view():
    m = random_log_odds_map(2)
    f = mm.DistanceField(m, max_distance=0.5, signed=True)
    # beyond the box is free space (unknown as free): pad with it
    occ = np.pad(occupancy_of(f), 1, constant_values=False)
    edt = scipy_ndimage.distance_transform_edt
    ref = (edt(~occ) - edt(occ))[1:-1, 1:-1, 1:-1]
    ref = np.clip(ref * f.resolution, -0.5, 0.5)
    assert np.abs(f.field - ref).max() < 1e-5
    view = f.field
    assert not view.flags.writeable and view.base is not None
    assert np.shares_memory(view, f.field)  # the same buffer, not a copy


def test_query_gradient_matches_finite_differences_and_outside_is_nan():
    m = random_log_odds_map(3)
    f = mm.DistanceField(m, max_distance=0.6)
    rng = np.random.default_rng(4)
    lo = np.array(f.origin)
    hi = lo + (np.array(f.shape) - 1) * f.resolution
    p = rng.uniform(lo, hi, (500, 3))
    d, g = f.query(p)
    h = 1e-7
    for a in range(3):
        e = np.zeros(3)
        e[a] = h
        fd = (f.query(p + e)[0] - f.query(p - e)[0]) / (2 * h)
        ok = np.isfinite(fd)
        assert np.abs(g[ok, a] - fd[ok]).max() < 1e-4 * max(1.0, np.abs(fd[ok]).max())
    d, g = f.query([[lo[0] - 1.0, lo[1], lo[2]]])
    assert np.isnan(d[0]) and np.isnan(g).all()
    obs = f.is_observed(p)
    assert obs.dtype == bool and obs.shape == (500,)


def test_incremental_update_equals_recompute():
    m = random_log_odds_map(5)
    f = mm.DistanceField(m, max_distance=0.4, incremental=True)
    view = f.field
    rng = np.random.default_rng(6)
    pts = rng.uniform(-1.5, 1.5, (300, 3)).astype(np.float32)
    pts[:, 2] *= 0.2
    m.insert_point_cloud(pts, np.zeros(3))
    report = f.update(m)
    assert report["changed_voxels"] > 0 and not report["full"]
    # the same box from scratch: scipy over the updated states
    occ = occupancy_of(f)
    ref = np.minimum(scipy_ndimage.distance_transform_edt(~occ) * f.resolution, 0.4)
    assert np.abs(view - ref).max() < 1e-5


def test_gil_released_while_the_field_is_computed():
    pts = np.random.default_rng(7).uniform(-6, 6, (2000, 3))
    ticks = []
    stop = threading.Event()

    def tick():
        while not stop.is_set():
            ticks.append(time.perf_counter())
            time.sleep(0)

    t = threading.Thread(target=tick)
    t.start()
    start = time.perf_counter()
    mm.DistanceField(pts, resolution=0.04, max_distance=1.0, threads=1)
    end = time.perf_counter()
    stop.set()
    t.join()
    middle = [x for x in ticks if start + (end - start) / 4 < x < end - (end - start) / 4]
    assert len(middle) > 0, f"no tick during {end - start:.3f} s"


def test_bad_input():
    with pytest.raises(ValueError):
        mm.DistanceField(np.zeros((3, 3)), max_distance=1.0)  # no resolution
    with pytest.raises(ValueError, match="max_distance"):
        mm.DistanceField(np.zeros((3, 3)), resolution=0.1, max_distance=float("nan"))
    with pytest.raises(ValueError, match="unknown"):
        mm.DistanceField(np.zeros((3, 3)), resolution=0.1, unknown="maybe")
    # numbers: a bound that underflows float32, a point-map cell edge outside what a map holds
    with pytest.raises(ValueError, match="float32"):
        mm.DistanceField(np.zeros((3, 3)), resolution=0.1, max_distance=1e-300)
    for resolution in (1e-300, 1e300):
        with pytest.raises(ValueError, match="resolution"):
            mm.DistanceField(np.zeros((3, 3)), resolution=resolution)
    field = mm.DistanceField(np.ones((3, 3)), resolution=0.1)
    # a 3D field is queried with x, y, z: two columns are not read as z = 0
    for query in (field.query, field.is_observed, field.nearest_obstacle):
        with pytest.raises(ValueError, match=r"\(N, 3\)"):
            query(np.ones((4, 2)))


def test_nearest_obstacle_is_the_nearest_occupied_centre_and_none_outside():
    rng = np.random.default_rng(3)
    pts = rng.uniform(0.0, 3.0, (60, 3))
    field = mm.DistanceField(pts, resolution=0.1, max_distance=1.0)
    occupied = field.origin + np.argwhere(occupancy_of(field)) * field.resolution
    probes = np.vstack([rng.uniform(0.0, 3.0, (200, 3)), [[1e300, 0, 0], [-1e300, 0, 0]]])
    positions, found = field.nearest_obstacle(probes)
    assert positions.shape == (202, 3) and found.dtype == np.bool_
    assert not found[-2:].any() and np.isnan(positions[-2:]).all()
    with pytest.raises(ValueError, match="row 1: nan is not a finite number"):
        field.nearest_obstacle([[1, 1, 1], [np.nan, 0, 0]])
    for p, q, ok in zip(probes[:-2], positions[:-2], found[:-2]):
        nearest = np.linalg.norm(occupied - p, axis=1).min()
        if ok:  # an occupied centre, and none nearer to p
            assert np.linalg.norm(occupied - q, axis=1).min() < 1e-9
            assert abs(np.linalg.norm(q - p) - nearest) < 1e-9
        else:  # only where p's voxel is at the clamp
            d, _ = field.query(p[None])
            assert d[0] >= field.max_distance - 1e-6 or np.isnan(d[0])


def test_update_from_a_map_of_another_resolution_is_refused():
    field = mm.DistanceField(random_log_odds_map(5), incremental=True)
    with pytest.raises(ValueError, match="resolution"):
        field.update(random_log_odds_map(5, resolution=0.2))


def test_write_vdb_writes_an_openvdb_file_atomically(tmp_path):
    """The voxel values themselves are read back through OpenVDB by the C++ suite
    (VdbWriter.*); here: the file opens with OpenVDB's magic number, a path that cannot be
    written raises OSError naming it and leaves nothing behind."""
    f = mm.DistanceField(np.random.default_rng(3).uniform(-1, 1, (200, 3)), resolution=0.1,
                         max_distance=0.3)
    out = tmp_path / "f.vdb"
    f.write_vdb(out)
    assert out.read_bytes()[:4] == bytes([0x20, 0x42, 0x44, 0x56])
    with pytest.raises(OSError, match="nodir"):
        f.write_vdb(tmp_path / "nodir" / "f.vdb")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["f.vdb"]
