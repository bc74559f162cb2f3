"""Slam2D, pose graphs and trajectory metrics from Python against independent oracles: the
`metricmap slam2d` and `metricmap posegraph` commands on the same data, g2o's chi² and the
relation metric of Kümmerle et al. (2009) written here in numpy."""

import json
import math
import subprocess

import numpy as np
import pytest

import metricmap as mm

INTEL = ("radish_clf_raw", "intel.clf.bz2")
FRAMES = 240  # a prefix of the Intel log; small submaps so that loops are searched


def run_cli(cli, *args):
    out = subprocess.run([cli, *map(str, args)], capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    return out.stdout


def yaw_of_quaternion(qx, qy, qz, qw):
    return np.arctan2(2 * (qw * qz + qx * qy), 1 - 2 * (qy * qy + qz * qz))


def wrap(a):
    return (np.asarray(a) + np.pi) % (2 * np.pi) - np.pi


@pytest.fixture(scope="module")
def slam_cli(cli, data, tmp_path_factory):
    d = tmp_path_factory.mktemp("slam2d")
    report = json.loads(
        run_cli(
            cli, "slam2d", data.joinpath(*INTEL), "--frames", f"0-{FRAMES - 1}", "--scans-per-submap", "15",
            "--out-poses", d / "poses.txt", "--out-map", d / "map.pgm", "--out-graph", d / "graph.g2o",
            "--format", "json",
        )
    )
    return d, report


@pytest.fixture(scope="module")
def slam_py(data):
    config = mm.Slam2DConfig(scans_per_submap=15)
    return mm.run_slam2d(data.joinpath(*INTEL), frames=range(FRAMES), config=config)


def test_slam2d_trajectory_equals_the_cli(slam_cli, slam_py):
    d, report = slam_cli
    rows = np.loadtxt(d / "poses.txt", ndmin=2)  # TUM, in stamp order
    traj, stamps = slam_py.trajectory, slam_py.stamps
    assert traj.shape == (FRAMES, 3) and len(stamps) == FRAMES == report["scans"]
    order = np.argsort(stamps, kind="stable")
    np.testing.assert_array_equal(stamps[order], rows[:, 0])  # %.9f of the log's 6 decimals
    np.testing.assert_allclose(traj[order, 0], rows[:, 1], atol=1e-8)
    np.testing.assert_allclose(traj[order, 1], rows[:, 2], atol=1e-8)
    np.testing.assert_allclose(wrap(traj[order, 2] - yaw_of_quaternion(*rows[:, 4:8].T)), 0, atol=1e-7)
    s = slam_py.stats
    assert s["nodes"] == report["nodes"] and s["submaps"] == report["submaps"]
    assert s["loop_searches"] == report["loop_searches"] > 0
    assert len(slam_py.loops) == report["loop_closures"]["kept"]


def test_slam2d_map_and_graph_equal_the_cli(slam_cli, slam_py, tmp_path):
    d, report = slam_cli
    slam_py.write_map(tmp_path / "map.pgm")
    assert (tmp_path / "map.pgm").read_bytes() == (d / "map.pgm").read_bytes()
    img = slam_py.map_image()
    pgm = (d / "map.pgm").read_bytes()
    h, w = img["image"].shape
    np.testing.assert_array_equal(np.frombuffer(pgm[-h * w :], np.uint8).reshape(h, w), img["image"])
    m = slam_py.map()
    assert m["occupied_cells"] == report["map"]["occupied_cells"]
    assert np.count_nonzero(~np.isnan(m["log_odds"])) == m["known_cells"]
    # occupied = log-odds >= logit(0.5) = 0: the trinary image's black pixels over the known
    # cells' bounds, flipped (the image's row 0 is the top)
    known = ~np.isnan(m["log_odds"])
    rows, cols = np.flatnonzero(known.any(axis=1)), np.flatnonzero(known.any(axis=0))
    crop = m["log_odds"][rows[0] : rows[-1] + 1, cols[0] : cols[-1] + 1]
    np.testing.assert_array_equal(np.flipud(crop >= 0), img["image"] == 0)
    np.testing.assert_array_equal(np.flipud(np.isnan(crop)), img["image"] == 205)
    assert img["origin"][0] == pytest.approx((m["min_i"] + cols[0]) * m["resolution"])
    graph = slam_py.graph
    assert graph.to_g2o() == (d / "graph.g2o").read_text()
    assert len(graph) == report["nodes"] and len(slam_py.node_scans) == len(graph)


def test_slam2d_scan_by_scan_equals_run_slam2d(data, slam_py):
    src = mm.open_scan_source(data.joinpath(*INTEL))
    assert src.info["planar"]
    slam = mm.Slam2D(mm.Slam2DConfig(scans_per_submap=15), sensor_to_base=src.info["sensor_to_base"])
    for k in range(FRAMES):
        scan = src[k]
        slam.add_scan(*scan.laser, odometry=scan.odometry, stamp=scan.stamp)
    slam.finish()
    np.testing.assert_array_equal(slam.trajectory, slam_py.trajectory)
    with pytest.raises(ValueError):
        slam.add_scan([0.0], [1.0])


def test_slam2d_config_attributes():
    c = mm.Slam2DConfig(max_range=12.5, map_resolution=0.1)
    assert c.max_range == 12.5 and c.map_resolution == 0.1
    c.loop_min_score = 0.7
    assert mm.Slam2D(c).config.loop_min_score == 0.7
    with pytest.raises(TypeError):
        mm.Slam2DConfig(no_such_parameter=1)
    c.resolution = -1.0
    with pytest.raises(ValueError):
        c.validate()
    with pytest.raises(ValueError):
        mm.Slam2D(c)


@pytest.mark.parametrize(
    "name,value",
    [("weak_direction_min_gain", 1.5), ("weak_direction_min_gain", float("nan")),
     ("weak_direction_information", -1.0), ("weak_direction_weight", float("inf"))])
def test_slam2d_weak_direction_fields_are_validated(name, value):
    c = mm.Slam2DConfig()
    assert c.weak_direction_weight == 10.0 and c.weak_direction_min_gain == 0.05
    setattr(c, name, value)
    with pytest.raises(ValueError, match=name):
        c.validate()


# --- pose graphs ------------------------------------------------------------------------------


def se2(x, y, t):
    c, s = math.cos(t), math.sin(t)
    return np.array([[c, -s, x], [s, c, y], [0, 0, 1.0]])


def to_vec(m):
    return np.array([m[0, 2], m[1, 2], math.atan2(m[1, 0], m[0, 0])])


def synthetic_g2o(path, seed=5):
    """A noisy 2D loop: 40 poses around a square, odometry edges and 6 loop edges."""
    rng = np.random.default_rng(seed)
    truth = []
    for k in range(40):
        side, f = divmod(k, 10)
        corners = [(0, 0), (10, 0), (10, 10), (0, 10)]
        (x0, y0), (x1, y1) = corners[side], corners[(side + 1) % 4]
        truth.append((x0 + (x1 - x0) * f / 10, y0 + (y1 - y0) * f / 10, side * math.pi / 2))
    est = [np.array(truth[0])]
    lines = []
    edges = [(k, k + 1) for k in range(39)] + [(39, 0), (35, 5), (30, 10), (25, 15), (20, 0), (38, 2)]
    meas = {}
    for i, j in edges:
        z = to_vec(np.linalg.inv(se2(*truth[i])) @ se2(*truth[j]))
        z += rng.normal(scale=[0.05, 0.05, 0.01])
        meas[(i, j)] = z
    for k in range(1, 40):  # initial guess: chained noisy odometry
        est.append(to_vec(se2(*est[-1]) @ se2(*meas[(k - 1, k)])))
    info = np.diag([400.0, 400.0, 10000.0])
    for k, p in enumerate(est):
        lines.append(f"VERTEX_SE2 {k} {p[0]!r} {p[1]!r} {p[2]!r}")
    for (i, j), z in meas.items():
        lines.append(f"EDGE_SE2 {i} {j} {z[0]!r} {z[1]!r} {z[2]!r} 400 0 0 400 0 10000")
    path.write_text("\n".join(lines) + "\n")
    return np.array(est), meas, info


def read_g2o_vertices(path):
    rows = [l.split() for l in path.read_text().splitlines() if l.startswith("VERTEX_SE2")]
    return np.array([[float(v) for v in r[2:5]] for r in rows])


def chi2_numpy(poses, meas, info):
    """g2o's SE(2) chi²: e = t2v(Z⁻¹ (X_i⁻¹ X_j)), angle wrapped; Σ eᵀ Ω e."""
    total = 0.0
    for (i, j), z in meas.items():
        e = to_vec(np.linalg.inv(se2(*z)) @ np.linalg.inv(se2(*poses[i])) @ se2(*poses[j]))
        e[2] = wrap(e[2])
        total += e @ info @ e
    return total


def test_posegraph_optimise_equals_the_cli_and_numpy_chi2(cli, tmp_path):
    g2o = tmp_path / "loop.g2o"
    est, meas, info = synthetic_g2o(g2o)
    out = tmp_path / "out.g2o"
    report = json.loads(run_cli(cli, "posegraph", g2o, "--out", out, "--max-iterations", "50", "--format", "json"))
    graph = mm.read_g2o(g2o)
    assert graph.dimension == 2 and len(graph) == 40 and graph.edge_count == len(meas)
    np.testing.assert_allclose(graph.chi2(), chi2_numpy(est, meas, info), rtol=1e-9)
    r = graph.optimize(max_iterations=50)
    assert r["initial_chi2"] == pytest.approx(report["initial_chi2"], rel=1e-12)
    assert r["final_chi2"] == pytest.approx(report["final_chi2"], rel=1e-9)
    assert r["final_chi2"] < r["initial_chi2"] / 10
    np.testing.assert_allclose(graph.poses, read_g2o_vertices(out), atol=1e-9)
    np.testing.assert_allclose(graph.chi2(), chi2_numpy(graph.poses, meas, info), rtol=1e-9)
    e = graph.edges()
    assert e["ends"].shape == (len(meas), 2) and e["information"].shape == (len(meas), 3, 3)
    np.testing.assert_allclose(e["chi2"].sum(), graph.chi2(), rtol=1e-12)
    graph.write(tmp_path / "again.g2o")
    np.testing.assert_array_equal(read_g2o_vertices(tmp_path / "again.g2o"), graph.poses)


def test_posegraph_built_in_python_equals_the_file(tmp_path):
    g2o = tmp_path / "loop.g2o"
    est, meas, info = synthetic_g2o(g2o, seed=9)
    g = mm.PoseGraph(2)
    for k, p in enumerate(est):
        assert g.add_vertex(k, p) == k
    for (i, j), z in meas.items():
        g.add_edge(i, j, z, info, loop=j != i + 1)
    np.testing.assert_allclose(g.chi2(), mm.read_g2o(g2o).chi2(), rtol=1e-12)
    assert list(g.fixed) == [True] + [False] * 39


# --- trajectory metrics -----------------------------------------------------------------------


def rot_z(t):
    c, s = math.cos(t), math.sin(t)
    return np.array([[c, -s, 0], [s, c, 0], [0, 0, 1.0]])


def rpy_matrix(roll, pitch, yaw):
    cr, sr, cp, sp = math.cos(roll), math.sin(roll), math.cos(pitch), math.sin(pitch)
    rx = np.array([[1, 0, 0], [0, cr, -sr], [0, sr, cr]])
    ry = np.array([[cp, 0, sp], [0, 1, 0], [-sp, 0, cp]])
    return rot_z(yaw) @ ry @ rx


def random_trajectory(rng, n):
    poses = np.tile(np.eye(4), (n, 1, 1))
    for k in range(n):
        poses[k, :3, :3] = rpy_matrix(*rng.normal(scale=[0.05, 0.05, 1.0]))
        poses[k, :3, 3] = rng.normal(scale=5.0, size=3)
    return poses


def test_relation_error_equals_numpy(tmp_path):
    rng = np.random.default_rng(11)
    n = 60
    stamps = 100.0 + 0.5 * np.arange(n)
    est = random_trajectory(rng, n)
    lines, expected_t, expected_r = [], [], []
    pairs = [(i, j) for i, j in rng.integers(0, n, size=(25, 2)) if i != j]
    for i, j in pairs:
        true_rel = np.linalg.inv(est[i]) @ est[j]
        rpy = rng.normal(scale=0.02, size=3)
        noisy = np.eye(4)
        noisy[:3, :3] = rpy_matrix(*rpy)
        noisy[:3, 3] = rng.normal(scale=0.1, size=3)
        rel = true_rel @ noisy
        # write the relation as the file's x y z roll pitch yaw
        r = rel[:3, :3]
        yaw = math.atan2(r[1, 0], r[0, 0])
        pitch = math.asin(-r[2, 0])
        roll = math.atan2(r[2, 1], r[2, 2])
        t = rel[:3, 3]
        lines.append(f"{stamps[i] + 0.001:.6f} {stamps[j] - 0.002:.6f} {t[0]!r} {t[1]!r} {t[2]!r} {roll!r} {pitch!r} {yaw!r}")
        rel_m = np.eye(4)
        rel_m[:3, :3] = rpy_matrix(roll, pitch, yaw)
        rel_m[:3, 3] = t
        err = np.linalg.inv(rel_m) @ (np.linalg.inv(est[i]) @ est[j])
        expected_t.append(np.linalg.norm(err[:3, 3]))
        expected_r.append(math.degrees(math.acos(np.clip((np.trace(err[:3, :3]) - 1) / 2, -1, 1))))
    lines.append(f"{stamps[-1] + 5:.6f} {stamps[0]:.6f} 1 0 0 0 0 0")  # no pose within 0.01 s
    path = tmp_path / "relations.txt"
    path.write_text("\n".join(lines) + "\n")
    res = mm.relation_error(est, stamps, path)
    assert res["used"] == len(pairs) and list(res["skipped"]) == [len(pairs)]
    np.testing.assert_allclose(res["translation"], expected_t, rtol=1e-9, atol=1e-12)
    np.testing.assert_allclose(res["rotation_deg"], expected_r, rtol=1e-6, atol=1e-6)
    et, er = np.array(expected_t), np.array(expected_r)
    assert res["translation_abs"]["mean"] == pytest.approx(et.mean(), rel=1e-9)
    assert res["translation_abs"]["std"] == pytest.approx(et.std(ddof=1), rel=1e-9)
    assert res["translation_sq"]["mean"] == pytest.approx((et**2).mean(), rel=1e-9)
    assert res["rotation_abs_deg"]["mean"] == pytest.approx(er.mean(), rel=1e-6)
    assert res["rotation_sq_deg"]["std"] == pytest.approx((er**2).std(ddof=1), rel=1e-5)
    # the same relations as arrays
    rs, rel = mm.read_relations(path)
    res2 = mm.relation_error(est, stamps, rel, relation_stamps=rs)
    np.testing.assert_array_equal(res2["translation"], res["translation"])


def test_relation_error_equals_the_cli(cli, tmp_path):
    rng = np.random.default_rng(4)
    est = random_trajectory(rng, 30)
    stamps = 10.0 + np.arange(30.0)
    mm.write_trajectory(tmp_path / "est.txt", est, stamps, format="tum")
    lines = [f"{stamps[i]:.6f} {stamps[i + 3]:.6f} 0.5 0.1 0 0 0 0.2" for i in range(0, 25, 2)]
    (tmp_path / "rel.txt").write_text("\n".join(lines) + "\n")
    report = json.loads(run_cli(cli, "evaluate", tmp_path / "est.txt", "--relations", tmp_path / "rel.txt", "--format", "json"))
    poses, st = mm.read_trajectory(tmp_path / "est.txt")
    res = mm.relation_error(poses, st, tmp_path / "rel.txt")
    assert res["used"] == report["relations"]["used"] == len(lines)
    for mine, theirs in [
        ("translation_abs", "abs_translation_m"),
        ("translation_sq", "sqr_translation_m2"),
        ("rotation_abs_deg", "abs_rotation_deg"),
        ("rotation_sq_deg", "sqr_rotation_deg2"),
    ]:
        assert res[mine]["mean"] == pytest.approx(report[theirs]["mean"], rel=1e-12)
        assert res[mine]["std"] == pytest.approx(report[theirs]["std"], rel=1e-12)


def test_ate_without_alignment_equals_numpy_and_file_round_trip(tmp_path):
    rng = np.random.default_rng(2)
    ref = random_trajectory(rng, 20)
    est = ref.copy()
    est[:, :3, 3] += rng.normal(scale=0.2, size=(20, 3))
    r = mm.evaluate_trajectory(est, ref, align="none")
    d = np.linalg.norm(est[:, :3, 3] - ref[:, :3, 3], axis=1)
    np.testing.assert_allclose(r["ate"]["translation"], d, rtol=1e-12)
    assert r["ate"]["translation_stats"]["rmse"] == pytest.approx(np.sqrt((d**2).mean()), rel=1e-12)
    assert r["paired_by"] == "index"
    mm.write_trajectory(tmp_path / "t.txt", est)
    back, stamps = mm.read_trajectory(tmp_path / "t.txt")
    assert stamps is None
    np.testing.assert_allclose(back, est, rtol=1e-8, atol=1e-9)
    # a rigidly moved copy aligns back to zero error
    move = np.eye(4)
    move[:3, :3] = rot_z(0.7)
    move[:3, 3] = [3, -2, 1]
    r = mm.evaluate_trajectory(move @ ref, ref, align="rigid")
    assert r["ate"]["translation_stats"]["max"] < 1e-9
    np.testing.assert_allclose(r["alignment"]["rotation"], rot_z(-0.7), atol=1e-9)


def test_relation_error_places_missing_stamps_by_the_odometry(cli, tmp_path):
    """A stamp the estimate lacks: the nearest estimated pose moved by the odometry's motion
    P(t) = P(t_n) O(t_n)^-1 O(t), computed in numpy here, and the CLI's --odometry agrees."""
    rng = np.random.default_rng(8)
    n = 40
    stamps = 5.0 + np.arange(n, dtype=float)
    truth = random_trajectory(rng, n)
    odo = random_trajectory(rng, n)  # its own world frame: only its motion counts
    keep = np.arange(0, n, 3)  # the estimate has every third stamp
    lines, expected = [], []
    for i in range(0, n - 5, 2):
        j = i + 5
        rel = np.linalg.inv(truth[i]) @ truth[j]
        r = rel[:3, :3]
        yaw, pitch, roll = math.atan2(r[1, 0], r[0, 0]), math.asin(-r[2, 0]), math.atan2(r[2, 1], r[2, 2])
        t = rel[:3, 3]
        lines.append(f"{stamps[i]:.6f} {stamps[j]:.6f} {t[0]!r} {t[1]!r} {t[2]!r} {roll!r} {pitch!r} {yaw!r}")

        def placed(k):
            m = keep[np.argmin(np.abs(stamps[keep] - stamps[k]))]  # nearest kept (earlier on ties)
            return truth[m] @ np.linalg.inv(odo[m]) @ odo[k]

        rel_m = np.eye(4)
        rel_m[:3, :3] = rpy_matrix(roll, pitch, yaw)
        rel_m[:3, 3] = t
        err = np.linalg.inv(rel_m) @ np.linalg.inv(placed(i)) @ placed(j)
        expected.append(np.linalg.norm(err[:3, 3]))
    (tmp_path / "rel.txt").write_text("\n".join(lines) + "\n")
    res = mm.relation_error(truth[keep], stamps[keep], tmp_path / "rel.txt",
                            odometry_poses=odo, odometry_stamps=stamps)
    assert res["used"] == len(lines) and res["stamps_placed_by_odometry"] > len(lines)
    np.testing.assert_allclose(res["translation"], expected, rtol=1e-7, atol=1e-9)
    assert max(expected) > 0.01  # the odometry differs from the truth: the test can fail
    # Without the odometry no relation has both stamps in the estimate: nothing to measure.
    with pytest.raises(mm.InputError, match="nothing to measure"):
        mm.relation_error(truth[keep], stamps[keep], tmp_path / "rel.txt")
    mm.write_trajectory(tmp_path / "est.txt", truth[keep], stamps[keep], format="tum")
    mm.write_trajectory(tmp_path / "odo.txt", odo, stamps, format="tum")
    report = json.loads(run_cli(cli, "evaluate", tmp_path / "est.txt", "--relations", tmp_path / "rel.txt",
                                "--odometry", tmp_path / "odo.txt", "--format", "json"))
    assert report["relations"]["used"] == len(lines)
    assert report["abs_translation_m"]["mean"] == pytest.approx(np.mean(expected), rel=1e-6)
    with pytest.raises(ValueError):
        mm.relation_error(truth[keep], stamps[keep], tmp_path / "rel.txt", odometry_poses=odo)
