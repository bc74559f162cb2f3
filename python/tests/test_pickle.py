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


def graph_arrays(g):
    e = g.edges()
    return [g.poses, g.ids, g.fixed] + [e[k] for k in sorted(e)]


@pytest.mark.parametrize("path", ["2d", "3d"])
def test_pose_graph(data, tmp_path, path):
    rng = np.random.default_rng(5)
    if path == "2d":
        g = mm.PoseGraph(2)
        for k in range(12):
            g.add_vertex(100 + k, [k + rng.normal(0, 0.1), rng.normal(0, 0.1), rng.normal(0, 0.05)])
        for k in range(11):
            g.add_edge(k, k + 1, [1.0, 0.0, 0.0], np.diag([50.0, 50.0, 200.0]))
        g.add_edge(0, 11, [11.0, 0.0, 0.0], np.eye(3) * 10, loop=True)
    else:
        g = mm.PoseGraph(3)
        for k in range(8):
            g.add_vertex(k, [k, rng.normal(0, 0.1), 0.0, 0.0, 0.0, 0.0, 1.0])
        for k in range(7):
            g.add_edge(k, k + 1, [1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0], np.eye(6))
    back = round_trip(g)
    assert back == g and back.dimension == g.dimension and back.chained_guess == g.chained_guess
    assert back.to_g2o() == g.to_g2o()
    for a, b in zip(graph_arrays(back), graph_arrays(g)):
        np.testing.assert_array_equal(a, b)
    # the loaded graph optimises as the original does
    ra, rb = g.optimize(), back.optimize()
    ra.pop("seconds"), rb.pop("seconds")
    assert ra == rb
    np.testing.assert_array_equal(g.poses, back.poses)
    assert copy.deepcopy(g) == g and g != mm.PoseGraph(g.dimension)


def test_pose_graph_read_from_g2o_pickles(tmp_path):
    text = "VERTEX_SE2 0 0 0 0\nVERTEX_SE2 1 1 0 0\nEDGE_SE2 0 1 1 0 0 1 0 0 1 0 1\n"
    (tmp_path / "g.g2o").write_text(text)
    g = mm.read_g2o(tmp_path / "g.g2o")
    assert round_trip(g) == g and round_trip(g).to_g2o() == g.to_g2o()


def test_map2d(tmp_path):
    img = np.full((6, 9), 205, np.uint8)
    img[1:3, 2:7] = 254
    img[4, 1] = 0
    (tmp_path / "m.pgm").write_bytes(b"P5\n9 6\n255\n" + img.tobytes())
    (tmp_path / "m.yaml").write_text("image: m.pgm\nresolution: 0.25\norigin: [1.5, -2.0, 0.3]\n"
                                     "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n")
    m = mm.read_map(tmp_path / "m.yaml")
    back = round_trip(m)
    assert back == m
    np.testing.assert_array_equal(back.cells, m.cells)
    # map_server's reading of the image, bottom row first: 0 (black) occupied, 254 free
    want = np.where(img[::-1] == 0, 100, np.where(img[::-1] == 254, 0, -1))
    np.testing.assert_array_equal(back.cells, want)
    assert (back.resolution, back.origin, back.width, back.height) == (0.25, (1.5, -2.0, 0.3), 9, 6)


def test_slam3d_config():
    c = mm.Slam3DConfig(loop_radius=7.5)
    back = round_trip(c)
    assert back == c and back != mm.Slam3DConfig() and back.loop_radius == 7.5
    assert copy.deepcopy(c) == c


def test_live_map_before_finish(data):
    source = mm.open_scan_source(data.joinpath(*INTEL))
    config = mm.Slam2DConfig(loop_min_score=0.9999)  # no loop closes: finish() adds no optimisation
    s = mm.Slam2D(config, sensor_to_base=source.info["sensor_to_base"])
    with pytest.raises(ValueError, match="no scan was added"):
        s.map()
    for k in range(120):
        s.add_scan(*source[k].laser, odometry=source[k].odometry, stamp=source[k].stamp)
    live = s.map()
    image = s.map_image()
    assert live["occupied_cells"] > 0
    s.finish()
    assert len(s.loops) == 0
    done = s.map()
    np.testing.assert_array_equal(live.pop("log_odds"), done.pop("log_odds"))
    assert live == done
    np.testing.assert_array_equal(image["image"], s.map_image()["image"])
    # and the run function's finished map over the same scans
    run = mm.run_slam2d(source, frames=range(120), config=config)
    np.testing.assert_array_equal(run.map()["log_odds"], s.map()["log_odds"])
