"""Bad input to the sequence, SLAM, pose-graph and evaluation entry points: each case raises a
Python exception (never a crash), also under the ASan stage of scripts/test."""

import numpy as np
import pytest

import metricmap as mm

I4 = np.tile(np.eye(4), (5, 1, 1))
STAMPS = np.arange(5.0)
NAN_POSES = I4.copy()
NAN_POSES[2, 0, 3] = np.nan
SHEARED = I4.copy()
SHEARED[1, 0, 1] = 0.5


def kitti(data):
    return data / "kitti_odometry_00"


def intel(data):
    return data / "radish_clf_raw" / "intel.clf.bz2"


def cases(data, tmp):
    missing = tmp / "missing"
    garbage = tmp / "garbage.g2o"
    garbage.write_text("VERTEX_SE2 0 0 0 nan\n")
    bad_rel = tmp / "rel.txt"
    bad_rel.write_text("1 2 3\n")
    bad_traj = tmp / "traj.txt"
    bad_traj.write_text("1 2 3 4 5\n")
    empty_dir = tmp / "empty"
    empty_dir.mkdir(exist_ok=True)
    src = mm.open_scan_source(kitti(data))
    return [
        # sources
        ("source missing", lambda: mm.open_scan_source(missing), OSError),
        ("source empty dir", lambda: mm.open_scan_source(empty_dir), OSError),
        ("source bad format", lambda: mm.open_scan_source(kitti(data), format="pcap"), ValueError),
        ("source bad sequence", lambda: mm.open_scan_source(kitti(data), sequence="99"), OSError),
        ("source path None", lambda: mm.open_scan_source(None), TypeError),
        ("scan index", lambda: src[len(src)], IndexError),
        ("scan negative index", lambda: src[-len(src) - 1], IndexError),
        ("scan index str", lambda: src["0"], TypeError),
        # odometry runs
        ("odometry frames decreasing", lambda: mm.run_odometry(src, frames=[2, 1]), ValueError),
        ("odometry frames out of range", lambda: mm.run_odometry(src, frames=[0, 99]), ValueError),
        ("odometry frames negative", lambda: mm.run_odometry(src, frames=[-1]), ValueError),
        ("odometry frames float", lambda: mm.run_odometry(src, frames=[0.5]), TypeError),
        ("odometry profile", lambda: mm.run_odometry(src, profile="car"), ValueError),
        ("odometry deskew", lambda: mm.run_odometry(src, deskew="yes"), ValueError),
        ("odometry NaN range", lambda: mm.run_odometry(src, max_range=float("nan")), ValueError),
        ("odometry source int", lambda: mm.run_odometry(3), TypeError),
        ("odometry missing path", lambda: mm.run_odometry(missing), OSError),
        # maps
        ("mapper poses shape", lambda: mm.SequenceMapper(src).build(np.eye(4)), ValueError),
        ("mapper poses count", lambda: mm.SequenceMapper(src).build(I4[:2]), ValueError),
        ("mapper poses NaN", lambda: mm.SequenceMapper(src).build(np.concatenate([I4, I4[:1]])[:6] * np.nan), ValueError),
        ("mapper poses sheared", lambda: mm.SequenceMapper(src).build(np.concatenate([SHEARED, I4[:1]])), ValueError),
        ("mapper poses complex", lambda: mm.SequenceMapper(src).build(np.zeros((6, 4, 4), complex)), TypeError),
        ("mapper before build", lambda: mm.SequenceMapper(src).hit_map(), ValueError),
        ("mapper bad resolution", lambda: mm.SequenceMapper(src, map_resolution=-1.0), ValueError),
        ("mapper write kind", lambda: mm.SequenceMapper(src).build(mm.reference_sensor_poses(src)).write_map(tmp / "m.pgm", kind="x"), ValueError),
        ("mapper write ext", lambda: mm.SequenceMapper(src).build(mm.reference_sensor_poses(src)).write_map(tmp / "m.png"), ValueError),
        ("mapper write dir", lambda: mm.SequenceMapper(src).build(mm.reference_sensor_poses(src)).write_map(missing / "m.pgm"), OSError),
        # 2D SLAM
        ("slam3d source", lambda: mm.run_slam2d(src), OSError),
        ("slam frames", lambda: mm.run_slam2d(intel(data), frames=[5, 5]), ValueError),
        ("slam config", lambda: mm.Slam2D(mm.Slam2DConfig(resolution=0.0)), ValueError),
        ("slam config NaN", lambda: mm.Slam2D(mm.Slam2DConfig(max_range=float("nan"))), ValueError),
        ("slam config type", lambda: mm.Slam2DConfig(max_range="far"), TypeError),
        ("slam lengths", lambda: mm.Slam2D().add_scan([0.0], [1.0, 2.0]), ValueError),
        ("slam ranges 2-D", lambda: mm.Slam2D().add_scan(np.ones((2, 2)), np.ones((2, 2))), ValueError),
        ("slam NaN angle", lambda: mm.Slam2D().add_scan([np.nan], [1.0]), ValueError),
        ("slam NaN odometry", lambda: mm.Slam2D().add_scan([0.0], [1.0], odometry=[0, np.nan, 0]), ValueError),
        ("slam huge odometry", lambda: mm.Slam2D().add_scan([0.0], [1.0], odometry=[1e300, 0, 0]), ValueError),
        ("slam huge sensor_to_base", lambda: mm.Slam2D(sensor_to_base=[0, -1e12, 0]), ValueError),
        ("slam odometry shape", lambda: mm.Slam2D().add_scan([0.0], [1.0], odometry=[0, 0]), ValueError),
        ("slam ranges strings", lambda: mm.Slam2D().add_scan([0.0], ["a"]), TypeError),
        ("slam sensor_to_base", lambda: mm.Slam2D(sensor_to_base=[0, 0]), ValueError),
        ("slam map before finish", lambda: mm.Slam2D().map(), ValueError),
        ("slam map kind", lambda: mm.run_slam2d(intel(data), frames=range(3)).map_image("x"), ValueError),
        # pose graphs
        ("g2o missing", lambda: mm.read_g2o(missing), OSError),
        ("g2o NaN", lambda: mm.read_g2o(garbage), ValueError),
        ("graph dimension", lambda: mm.PoseGraph(4), ValueError),
        ("graph vertex shape", lambda: mm.PoseGraph(2).add_vertex(0, [0, 0]), ValueError),
        ("graph vertex NaN", lambda: mm.PoseGraph(2).add_vertex(0, [0, 0, np.nan]), ValueError),
        ("graph vertex negative id", lambda: mm.PoseGraph(2).add_vertex(-1, [0, 0, 0]), ValueError),
        ("graph edge to nowhere", lambda: mm.PoseGraph(2).add_edge(0, 1, [1, 0, 0], np.eye(3)), ValueError),
        ("graph edge negative", lambda: mm.PoseGraph(2).add_edge(-1, 1, [1, 0, 0], np.eye(3)), TypeError),
        ("graph optimise iterations", lambda: mm.PoseGraph(2).optimize(max_iterations=0), ValueError),
        ("graph optimise loss", lambda: mm.PoseGraph(2).optimize(loop_loss="l1"), ValueError),
        ("graph write dir", lambda: mm.PoseGraph(2).write(missing / "g.g2o"), OSError),
        # evaluation
        ("trajectory missing", lambda: mm.read_trajectory(missing), OSError),
        ("trajectory malformed", lambda: mm.read_trajectory(bad_traj), ValueError),
        ("trajectory format", lambda: mm.read_trajectory(bad_traj, format="csv"), ValueError),
        ("write trajectory format", lambda: mm.write_trajectory(tmp / "t.txt", I4, format="csv"), ValueError),
        ("write trajectory dir", lambda: mm.write_trajectory(missing / "t.txt", I4), OSError),
        ("write trajectory stamps", lambda: mm.write_trajectory(tmp / "t.txt", I4, STAMPS[:2], format="tum"), ValueError),
        ("evaluate shapes", lambda: mm.evaluate_trajectory(I4[:, :3], I4), ValueError),
        ("evaluate NaN", lambda: mm.evaluate_trajectory(NAN_POSES, I4), ValueError),
        ("evaluate empty", lambda: mm.evaluate_trajectory(I4[:0], I4), ValueError),
        ("evaluate align", lambda: mm.evaluate_trajectory(I4, I4, align="affine"), ValueError),
        ("evaluate time diff", lambda: mm.evaluate_trajectory(I4, I4, max_time_diff=-1.0), ValueError),
        ("relations missing", lambda: mm.read_relations(missing), OSError),
        ("relations malformed", lambda: mm.read_relations(bad_rel), ValueError),
        ("relation stamps NaN", lambda: mm.relation_error(I4, STAMPS * np.nan, bad_rel), ValueError),
        ("relation stamps count", lambda: mm.relation_error(I4, STAMPS[:3], bad_rel), ValueError),
        ("relation arrays without stamps", lambda: mm.relation_error(I4, STAMPS, I4), ValueError),
        ("relation arrays stamps shape", lambda: mm.relation_error(I4, STAMPS, I4, np.zeros(5)), ValueError),
        ("relation arrays NaN", lambda: mm.relation_error(I4, STAMPS, I4, np.full((5, 2), np.nan)), ValueError),
    ]


@pytest.fixture(scope="module")
def table(data, tmp_path_factory):
    return {name: (fn, exc) for name, fn, exc in cases(data, tmp_path_factory.mktemp("bad"))}




def _names():
    import pathlib
    import tempfile

    data = pathlib.Path(__file__).resolve().parents[2] / "data"
    with tempfile.TemporaryDirectory() as d:
        return [c[0] for c in cases(data, pathlib.Path(d))]


@pytest.mark.parametrize("name", _names())
def test_bad_input_raises(table, name):
    fn, exc = table[name]
    with pytest.raises(exc):
        fn()
