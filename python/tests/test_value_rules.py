"""The Python entry points of the library's value rules: tiny beam cuts, nothing done, files the
reader would refuse, poses and numbers beyond their bounds, values given then replaced, empty
selections. Each raises the documented exception with a message naming the value."""

import math
import pathlib

import numpy as np
import pytest

import metricmap as mm

INTEL = pathlib.Path(__file__).resolve().parents[2] / "data" / "radish_clf_raw" / "intel.clf.bz2"

I4 = np.eye(4)


def ring_folder(tmp, radius=8.0, n=400, scans=2):
    a = 2 * math.pi * np.arange(n) / n
    pts = np.stack([radius * np.cos(a), radius * np.sin(a), 0.1 * (np.arange(n) % 7)], 1).astype(np.float32)
    for k in range(scans):
        np.save(tmp / f"{k:03d}.npy", pts)
    return tmp


def refusals(tmp):
    pts = np.array([[1.0, 0.0, 0.0], [2.0, 1.0, 0.5]], np.float32)
    three = np.stack([I4, I4, I4])
    return [
        # tiny beam cuts
        ("log-odds max_range 1e-23", lambda: mm.LogOddsMap(0.1).insert_point_cloud(pts, [0, 0, 0], max_range=1e-23),
         ValueError, "max_range must be >= 0.001 m"),
        ("log-odds max_range 1e-4", lambda: mm.LogOddsMap(0.1).insert_point_cloud(pts, [0, 0, 0], max_range=1e-4),
         ValueError, "got 0.0001"),
        # nothing done
        ("optimise an empty graph", lambda: mm.PoseGraph(2).optimize(), ValueError, "0 vertices and no edge"),
        # files the reader would refuse
        ("TUM stamps twice", lambda: mm.write_trajectory(tmp / "t.txt", three, [0.0, 2.0, 0.0], format="tum"),
         ValueError, "poses 0 and 2 have the same stamp"),
        ("TUM stamps equal as written", lambda: mm.write_trajectory(tmp / "t.txt", three, [0.0, 1e-10, 1.0],
                                                                    format="tum"), ValueError, "as written"),
        # poses and numbers beyond their bounds
        ("graph vertex 1e30", lambda: mm.PoseGraph(2).add_vertex(0, [1e30, 0, 0]), ValueError, "beyond 1000000 m"),
        ("graph theta 1e17", lambda: mm.PoseGraph(2).add_vertex(0, [0, 0, 1e17]), ValueError, "theta 1e+17"),
        ("depth scale underflow", lambda: mm.depth_to_cloud(np.full((4, 5), 7, np.uint16), 500, 500, 2, 2, 1e-300),
         ValueError, "below float range"),
        ("grid cell 1e39", lambda: mm.grid(pts, 1e39), ValueError, "cell_size 1e+39"),
        ("grid finer than float32", lambda: mm.grid(np.array([[1e7, 0, 0], [10000001, 0, 0]], np.float32), 0.1),
         mm.CapacityError, "finer than float32"),
        ("height map reflection", lambda: mm.HeightMap(map_size=64).add_frame(pts, np.diag([1.0, 1.0, -1.0, 1.0])),
         ValueError, "rotation"),
        # a value given, then replaced
        ("given min_range above the chosen window", lambda: mm.run_odometry(str(ring_folder(tmp / "rings")),
                                                                            min_range=50.0),
         ValueError, "min_range 50 m (given)"),
    ]


@pytest.mark.parametrize("index", range(12))
def test_refused_with_a_message_naming_the_value(tmp_path, index):
    (tmp_path / "rings").mkdir()
    name, call, error, needle = refusals(tmp_path)[index]
    with pytest.raises(error) as e:
        call()
    assert needle in str(e.value), (name, str(e.value))
    assert not (tmp_path / "t.txt").exists(), name


def test_the_limits_themselves_are_accepted(tmp_path):
    pts = np.array([[1.0, 0.0, 0.0], [2.0, 1.0, 0.5]], np.float32)
    m = mm.LogOddsMap(0.1)
    m.insert_point_cloud(pts, [0, 0, 0], max_range=0.001)
    g = mm.PoseGraph(2)
    g.add_vertex(0, [1e6, -1e6, 1e6])
    mm.write_trajectory(tmp_path / "t.txt", np.stack([I4, I4]), [0.0, 1e-9], format="tum")
    poses, stamps = mm.read_trajectory(tmp_path / "t.txt")
    np.testing.assert_allclose(stamps, [0.0, 1e-9], atol=1e-12)


def small_map(tmp):
    """A 20 x 20 map_server map of 0.1 m cells: occupied border, free inside."""
    img = np.full((20, 20), 254, np.uint8)
    img[0, :] = img[-1, :] = img[:, 0] = img[:, -1] = 0
    (tmp / "m.pgm").write_bytes(b"P5\n20 20\n255\n" + img.tobytes())
    (tmp / "m.yaml").write_text("image: m.pgm\nresolution: 0.1\norigin: [0, 0, 0]\nnegate: 0\n"
                                "occupied_thresh: 0.65\nfree_thresh: 0.196\n")
    return tmp / "m.yaml"


def refusals6(tmp):
    """Unread values, options without effect, files the readers refuse, exception
    types and messages quoting the value given."""
    pts = np.array([[1.0, 0.0, 0.0], [2.0, 1.0, 0.5]], np.float32)
    angles = np.linspace(-1.5, 1.5, 181)
    far = np.full(181, 3.0)
    far[::2] = 1e300
    three = np.stack([I4, I4, I4])
    yaml = small_map(tmp)
    return [
        # nothing done yet
        ("odometry result before any frame", lambda: mm.LidarOdometry().last_result, ValueError, "no frame yet"),
        # numbers beyond float32
        ("split_and_merge range 1e300", lambda: mm.split_and_merge(angles, far), ValueError, "range 1e+300"),
        ("split_and_merge range 1e39", lambda: mm.split_and_merge(angles, np.where(far > 3, 1e39, 3.0)),
         ValueError, "range 1e+39"),
        ("octree min_cell_size 1e-300", lambda: mm.octree(pts, max_points=1, min_cell_size=1e-300),
         ValueError, "min_cell_size 1e-300 is outside the single-precision range"),
        ("octree min_cell_size 1e39", lambda: mm.octree(pts, max_points=1, min_cell_size=1e39),
         ValueError, "min_cell_size 1e+39"),
        # angles beyond the CLI's bounds
        ("camera pitch 1e17", lambda: mm.camera_to_map(1.0, 1e17), ValueError, "pitch 1e+17"),
        ("camera pitch just past 90 degrees", lambda: mm.camera_to_map(1.0, math.pi / 2 + 1e-6), ValueError,
         "-90 to 90 degrees"),
        ("camera yaw 1e30", lambda: mm.camera_to_map(1.0, 0.1, yaw=1e30), ValueError, "yaw 1e+30"),
        # non-finite query points
        ("distance query NaN", lambda: mm.DistanceField(yaml).query([[np.nan, 0, 0]]), ValueError, "nan"),
        ("nearest obstacle NaN", lambda: mm.DistanceField(yaml).nearest_obstacle([[0.5, np.nan]]), ValueError,
         "row 0: nan"),
        ("is_observed inf", lambda: mm.DistanceField(yaml).is_observed([[1, 1, 0], [np.inf, 0, 0]]), ValueError,
         "row 1: inf"),
        # options that change nothing
        ("purge with nothing to purge", lambda: mm.split_and_merge(angles, np.full(181, 3.0), purge="after-merge",
                                                                  min_points=0, min_length=0),
         ValueError, "purge has no effect with min_points 0 and min_length 0"),
        ("purge without merging", lambda: mm.split_and_merge(angles, np.full(181, 3.0), purge="before-merge",
                                                            angle_threshold=0),
         ValueError, "purge has no effect with angle_threshold 0"),
        ("incremental 2D field", lambda: mm.DistanceField(yaml, incremental=True), ValueError,
         "incremental has no effect"),
        # files the readers would refuse
        ("PCD of no points", lambda: mm.write_pcd(tmp / "e.pcd", np.zeros((0, 3))), ValueError, "0 points"),
        # exception types
        ("DistanceField(123)", lambda: mm.DistanceField(123), TypeError, "got int"),
        ("height map empty frame", lambda: mm.HeightMap(map_size=64).add_frame(np.zeros((0, 3)), I4), ValueError,
         "0 points"),
        # messages naming the parameter
        ("TUM stamp inf", lambda: mm.write_trajectory(tmp / "t.txt", three, stamps=[0, 1, math.inf], format="tum"),
         ValueError, "stamps must be finite"),
    ]


@pytest.mark.parametrize("index", range(18))
def test_refused_numbers_and_files(tmp_path, index):
    name, call, error, needle = refusals6(tmp_path)[index]
    with pytest.raises(error) as e:
        call()
    assert needle in str(e.value), (name, str(e.value))
    assert not (tmp_path / "t.txt").exists() and not (tmp_path / "e.pcd").exists(), name
    if name == "TUM stamp inf":
        assert not str(e.value).startswith("poses_"), str(e.value)


def test_their_limits_are_accepted(tmp_path):
    """The bounds themselves and the defaults still work: the refusals above are not blanket."""
    pts = np.array([[1.0, 0.0, 0.0], [2.0, 1.0, 0.5]], np.float32)
    odo = mm.LidarOdometry()
    with pytest.raises(ValueError):
        odo.last_result
    (tmp_path / "rings").mkdir()
    ring = ring_folder(tmp_path / "rings")
    odo.register_frame(np.load(ring / "000.npy"))
    assert odo.last_result["points_in"] == 400
    odo.reset()
    with pytest.raises(ValueError):
        odo.last_result
    # 90 and 360 degrees themselves, converted as the CLI does; an oracle for the rotation
    t = mm.camera_to_map(1.5, 90 * math.pi / 180, yaw=-360 * math.pi / 180)
    np.testing.assert_allclose(t[:3, 2], [0, 0, -1], atol=1e-12)  # optical axis straight down
    assert t[2, 3] == 1.5
    angles = np.linspace(-1.5, 1.5, 181)
    r = np.full(181, 3.0)
    r[0] = 3e38  # within float32: a (far) point, not an error
    assert len(mm.split_and_merge(angles, r)["start"]) == 1
    arc = np.full(181, 3.0)
    np.testing.assert_array_equal(mm.split_and_merge(angles, arc, purge="before-merge")["start"],
                                  mm.split_and_merge(angles, arc)["start"])
    assert "9 nodes, 8 leaves" in repr(mm.octree(pts, max_points=1, min_cell_size=0.0))  # one split
    yaml = small_map(tmp_path)
    f = mm.DistanceField(yaml)
    d, _ = f.query([[1.0, 1.0, 0.0]])  # centre of the 2 m box: 0.9 m from the border cells' centres
    assert d[0] == pytest.approx(0.9, abs=1e-6)
    assert mm.DistanceField(pts, resolution=0.1, incremental=True).dimensions == 3
    mm.write_pcd(tmp_path / "one.pcd", pts[:1])
    assert mm.read_points(tmp_path / "one.pcd").shape == (1, 4)


def test_pcd_header_warning_as_the_cli_prints_it(tmp_path):
    p = tmp_path / "w0.pcd"
    pts = np.arange(30, dtype=np.float32).reshape(10, 3)
    p.write_bytes(b"VERSION .7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 0\nHEIGHT 0\n"
                  b"VIEWPOINT 0 0 0 1 0 0 0\nPOINTS 10\nDATA binary\n" + pts.tobytes())
    for read in (mm.read_points, mm.read_cloud):
        with pytest.warns(UserWarning, match="header says WIDTH 0 HEIGHT 0 but POINTS 10") as w:
            read(p)
        assert len(w) == 1
    with pytest.warns(UserWarning):
        np.testing.assert_array_equal(mm.read_points(p)[:, :3], pts)
    assert mm.cloud_info(p)["warnings"] == [str(w[0].message)]


def refusals6b(tmp):
    """Objects and selections: empty or unordered selections, options without effect
    on the scan runs, a map a file cannot hold, edges the g2o reader refuses, messages in the
    shortest number form."""
    (tmp / "rings").mkdir(exist_ok=True)
    rings = str(ring_folder(tmp / "rings"))
    pcd = tmp / "p.pcd"
    mm.write_pcd(pcd, np.array([[1.0, 0.0, 0.0], [2.0, 1.0, 0.5]]))
    graph = mm.PoseGraph(2)
    graph.add_vertex(0, [0, 0, 0])
    graph.add_vertex(1, [1, 0, 0])
    return [
        # empty or unordered selections
        ("compare no configs", lambda: mm.compare([pcd], configs=[]), ValueError, "configs is empty"),
        ("compare no paths", lambda: mm.compare([]), ValueError, "paths is empty"),
        ("frames an empty set", lambda: mm.run_odometry(rings, frames=set()), ValueError, "frames is empty"),
        ("frames a set", lambda: mm.run_odometry(rings, frames={0, 1}), TypeError,
         "frames must be ordered (a set has no order)"),
        ("mapper frames a set", lambda: mm.SequenceMapper(rings).build(np.stack([I4, I4]), frames={0, 1}), TypeError,
         "a set has no order"),
        # options without effect
        ("profile with all three values", lambda: mm.run_odometry(rings, profile="kitti", max_range=50, min_range=1,
                                                                 voxel_size=0.5),
         ValueError, "profile has no effect with max_range, min_range and voxel_size all given"),
        ("loop parameter without loop closure",
         lambda: mm.run_slam2d(INTEL, config=mm.Slam2DConfig(loop_min_score=0.7), loop_closure=False),
         ValueError, "config.loop_min_score has no effect with loop_closure=False"),
        ("band_2d without a 2D grid", lambda: mm.SequenceMapper(rings, band_2d=(0, 1)), ValueError,
         "band_2d has no effect without occupancy_2d_resolution"),
        ("2D max range without a 2D grid", lambda: mm.SequenceMapper(rings, occupancy_2d_max_range=5), ValueError,
         "occupancy_2d_max_range has no effect"),
        # a map no OctoMap file can hold
        ("log-odds resolution 5e-5", lambda: mm.LogOddsMap(5e-5), ValueError, "must be in [0.0001, 1e3], got 5e-5"),
        ("log-odds resolution 2000", lambda: mm.LogOddsMap(2000.0), ValueError, "got 2e3"),
        ("log-odds resolution 1e39", lambda: mm.LogOddsMap(1e39), ValueError, "got 1e39"),
        # an edge the g2o reader would refuse
        ("edge chi2 overflows", lambda: graph.add_edge(0, 1, [1e5, 0, 0], np.eye(3) * 1e300), ValueError,
         "chi² at the vertices' current poses is not finite"),
        # messages: the value given, in the shortest form
        ("mapper min range above max", lambda: mm.SequenceMapper(rings, min_range=50, max_range=30), ValueError,
         "min range 50 exceeds max range 30"),
        ("mapper resolution -1", lambda: mm.SequenceMapper(rings, map_resolution=-1), ValueError, "got -1"),
        ("mapper band order", lambda: mm.SequenceMapper(rings, occupancy_2d_resolution=0.1, band_2d=(1, 0.5)),
         ValueError, "got 1,0.5"),
        ("mapper voxel 1e39", lambda: mm.SequenceMapper(rings, voxel=1e39), ValueError, "voxel 1e+39"),
        ("origin 1e39", lambda: mm.LogOddsMap(0.2).insert_point_cloud(np.array([[1.0, 0, 0]]), [0, 1e39, 0]),
         ValueError, "origin[1] 1e+39"),
        ("depth fx 1e-300", lambda: mm.depth_to_cloud(np.full((4, 4), 1000, np.uint16), 1e-300, 525, 2, 2, 0.001),
         ValueError, "fx 1e-300"),
    ]


@pytest.mark.parametrize("index", range(19))
def test_refused_selections_and_object_calls(tmp_path, index):
    name, call, error, needle = refusals6b(tmp_path)[index]
    with pytest.raises(error) as e:
        call()
    assert needle in str(e.value), (name, str(e.value))
    assert ".000000" not in str(e.value), (name, str(e.value))


def test_objects_at_their_limits(tmp_path, capfd):
    """The accepted side of the rules above, and the file round trips they protect."""
    for res in (1e-4, 1000.0):
        assert mm.LogOddsMap(res).resolution == res
    m = mm.LogOddsMap(0.25)
    assert "resolution 0.25," in repr(m)
    m.insert_point_cloud(np.array([[1.0, 0.0, 0.0]]), [0, 0, 0])
    capfd.readouterr()
    m.write(tmp_path / "a.bt")
    back = mm.LogOddsMap.read(tmp_path / "a.bt")
    out, err = capfd.readouterr()
    assert out == "" and err == "", (out, err)  # liboctomap's chatter is muted
    assert back.resolution == 0.25
    np.testing.assert_allclose(back.extract_point_cloud()[0], m.extract_point_cloud()[0])
    g = mm.PoseGraph(2)
    g.add_vertex(0, [0, 0, 0])
    g.add_vertex(1, [1, 0, 0])
    g.add_edge(0, 1, [1.5, 0, 0], np.eye(3) * 1e3)  # chi² 0.25 x 1e3
    assert g.chi2() == pytest.approx(250.0)
    g.write(tmp_path / "g.g2o")
    assert mm.read_g2o(tmp_path / "g.g2o").chi2() == pytest.approx(250.0)
    (tmp_path / "rings").mkdir()
    rings = str(ring_folder(tmp_path / "rings"))
    run = mm.run_odometry(rings, frames=(k for k in [0, 1]), max_range=50, min_range=1, voxel_size=0.5)
    assert list(run["frames"]) == [0, 1]
    s = mm.SequenceMapper(rings, occupancy_2d_resolution=0.2, occupancy_2d_max_range=5, band_2d=(-1, 1))
    s.build(np.stack([I4, I4]))
    assert s.occupancy_2d() is not None


def test_memory_budget_from_python(tmp_path):
    before = mm.memory_budget()
    try:
        mm.set_memory_budget("64M")
        assert mm.memory_budget() == 64 << 20
        mm.set_memory_budget(1 << 30)
        assert mm.memory_budget() == 1 << 30
        for call in (lambda: mm.DistanceField(np.array([[0, 0, 0], [3000, 3000, 300.0]]), resolution=0.01),
                     lambda: mm.HeightMap(map_size=200000)):
            with pytest.raises(mm.CapacityError) as e:
                call()
            assert "metricmap.set_memory_budget" in str(e.value) and "--max-memory" not in str(e.value)
            assert "1024 MiB" in str(e.value), str(e.value)
        for bad, error in (("0", ValueError), (0, ValueError), (-5, ValueError), ("lots", ValueError),
                           (1.5, TypeError), (True, TypeError)):
            with pytest.raises(error):
                mm.set_memory_budget(bad)
        assert mm.memory_budget() == 1 << 30  # a refused value changes nothing
    finally:
        mm.set_memory_budget(before)
