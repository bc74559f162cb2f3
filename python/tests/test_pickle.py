"""Maps, configurations and SLAM results pickle and load to equal objects: compared field by
field with the original (arrays, voxels, the graph's g2o text, the map's cells), and with what
the original writes to files."""

import copy
import pickle

import numpy as np
import pytest

import metricmap as mm

INTEL = ("radish_clf_raw", "intel.clf.bz2")


def round_trip(obj):
    return pickle.loads(pickle.dumps(obj, protocol=pickle.HIGHEST_PROTOCOL))


def sorted_voxels(m):
    keys, values = m.voxels()
    order = np.lexsort(keys.T[::-1])
    return keys[order], values[order]


def test_log_odds_map(data, tmp_path):
    rng = np.random.default_rng(1)
    m = mm.LogOddsMap(resolution=0.2, prob_hit=0.8)
    m.insert_point_cloud(rng.uniform(-3, 3, (500, 3)), origin=(0, 0, 0), max_range=4.0)
    back = round_trip(m)
    assert back == m and back is not m and back.known_voxels == m.known_voxels > 0
    for got, want in zip(sorted_voxels(back), sorted_voxels(m)):
        np.testing.assert_array_equal(got, want)
    m.write(tmp_path / "a.ot")
    back.write(tmp_path / "b.ot")
    assert (tmp_path / "a.ot").read_bytes() == (tmp_path / "b.ot").read_bytes()
    # the parameters travel too: the next scan updates both alike
    more = rng.uniform(-3, 3, (200, 3))
    m.insert_point_cloud(more, origin=(0.5, 0, 0), max_range=4.0)
    assert back != m
    back.insert_point_cloud(more, origin=(0.5, 0, 0), max_range=4.0)
    assert back == m
    assert copy.deepcopy(m) == m


def test_log_odds_map_read_is_quiet_and_pickles(data, capfd):
    m = mm.LogOddsMap.read(data / "octomap_geb079" / "geb079.bt")
    assert capfd.readouterr().err == ""  # liboctomap's own progress lines are not printed
    assert round_trip(m) == m


def test_grid(data):
    pts = mm.read_points(data / "pcl_test_pcd" / "bunny.pcd")
    g = mm.grid(pts, cell_size=0.01)
    back = round_trip(g)
    assert back == g and len(back) == len(g) > 0
    for name in ("indices", "counts", "means", "first_points"):
        np.testing.assert_array_equal(getattr(back, name), getattr(g, name))
    assert (back.min_index, back.dims, back.origin, back.cell_size) == (
        g.min_index, g.dims, g.origin, g.cell_size)
    assert back.statistics == g.statistics
    assert g != mm.grid(pts, cell_size=0.02)


def test_slam2d_config():
    c = mm.Slam2DConfig(max_range=12.5, scans_per_submap=30, map_resolution=0.1)
    back = round_trip(c)
    assert back == c and back != mm.Slam2DConfig()
    for name in dir(c):
        if not name.startswith("_") and not callable(getattr(c, name)):
            assert getattr(back, name) == getattr(c, name), name
    assert eval(repr(c), {"Slam2DConfig": mm.Slam2DConfig}) == c


@pytest.fixture(scope="module")
def slam(data):
    return mm.run_slam2d(data.joinpath(*INTEL), frames=range(150),
                         config=mm.Slam2DConfig(scans_per_submap=15))


def test_slam2d_result(slam, tmp_path):
    back = round_trip(slam)
    np.testing.assert_array_equal(back.trajectory, slam.trajectory)
    np.testing.assert_array_equal(back.stamps, slam.stamps)
    np.testing.assert_array_equal(back.node_scans, slam.node_scans)
    assert back.loops == slam.loops and back.stats == slam.stats and back.config == slam.config
    assert back.graph.to_g2o() == slam.graph.to_g2o()
    assert back.graph.chi2() == slam.graph.chi2()
    a, b = slam.map(), back.map()
    np.testing.assert_array_equal(a.pop("log_odds"), b.pop("log_odds"))
    assert a == b
    slam.write_map(tmp_path / "a.pgm")
    back.write_map(tmp_path / "b.pgm")
    assert (tmp_path / "a.pgm").read_bytes() == (tmp_path / "b.pgm").read_bytes()
    with pytest.raises(ValueError, match="after finish"):
        back.add_scan([0.0], [1.0])


def test_a_running_slam2d_does_not_pickle():
    s = mm.Slam2D()
    s.add_scan([0.0, 0.1], [1.0, 1.0])
    with pytest.raises(TypeError, match="finish"):
        pickle.dumps(s)
