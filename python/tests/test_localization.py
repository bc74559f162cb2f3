"""metricmap.read_map / Localizer2D / run_localize2d: a map_server map read as map_server's
rules (written out here) say, the Intel log localised in a map that Slam2D made of it (its poses
at SLAM's, an independent estimate of the same scans), the object and the run function giving
the same answers, and bad input refused."""

import threading

import numpy as np
import pytest

import metricmap as mm


@pytest.fixture(scope="module")
def intel(data, tmp_path_factory):
    log = data / "radish_clf_raw" / "intel.clf.bz2"
    if not log.is_file():
        pytest.skip(f"{log} missing")
    slam = mm.run_slam2d(log, frames=range(600))
    out = tmp_path_factory.mktemp("loc") / "intel.pgm"
    slam.write_map(out)
    return log, slam, out.with_suffix(".yaml")


def test_read_map_follows_map_servers_trinary_rule(intel):
    _, _, yaml = intel
    m = mm.read_map(yaml)
    raw = yaml.with_suffix(".pgm").read_bytes()
    w, h = m.width, m.height
    img = np.frombuffer(raw[-w * h:], np.uint8).reshape(h, w)
    p = (255.0 - img) / 255.0  # negate: 0
    want = np.where(p > 0.65, 100, np.where(p < 0.196, 0, -1)).astype(np.int8)[::-1]
    assert m.cells.dtype == np.int8 and m.cells.shape == (h, w)
    assert (m.cells == want).all()
    assert m.resolution == pytest.approx(0.05) and len(m.origin) == 3
    assert (m.cells == 100).sum() > 1000 and (m.cells == 0).sum() > 10000


def test_run_localize2d_fixes_and_tracks_at_slams_poses(intel):
    log, slam, yaml = intel
    seen = []
    run = mm.run_localize2d(log, yaml, frames=range(300, 500), progress=lambda d, t: seen.append(d))
    assert isinstance(run, mm.LocalizationRun) and seen[-1] == 200
    assert run.stats["first_fix"] is not None and run.stats["first_fix"] < 20
    assert run.localised.sum() >= 0.95 * 200 and run.status[run.stats["first_fix"]] == "fixed"
    assert list(run.frames) == list(range(300, 500))
    assert np.isnan(run.poses[~run.localised]).all()
    # SLAM's pose of every scan (its trajectory has one row per scan added: 0-599)
    ok = run.localised
    errors = np.hypot(*(run.poses[ok, :2] - slam.trajectory[run.frames[ok], :2]).T)
    assert np.median(errors) <= 0.05 and np.percentile(errors, 95) <= 0.15, np.median(errors)


def test_the_object_gives_what_the_run_function_gives(intel):
    log, _, yaml = intel
    run = mm.run_localize2d(log, mm.read_map(yaml), frames=range(300, 340))
    source = mm.open_scan_source(log)
    loc = mm.Localizer2D(yaml, sensor_to_base=[source.info["sensor_to_base"][i][3] for i in (0, 1)]
                         + [np.arctan2(source.info["sensor_to_base"][1][0],
                                       source.info["sensor_to_base"][0][0])])
    for i, k in enumerate(range(300, 340)):
        scan = source[k]
        r = loc.localize(*scan.laser, odometry=scan.odometry)
        assert r.status == run.status[i]
        if r.localised:
            assert np.allclose(r.pose, run.poses[i], atol=1e-9)
        else:
            assert r.pose is None
    assert loc.stats["scans"] == 40 and loc.status == run.status[-1]


def test_calls_from_four_threads_are_serialised(intel):
    log, _, yaml = intel
    source = mm.open_scan_source(log)
    scans = [source[k] for k in range(300, 340)]
    loc = mm.Localizer2D(yaml)
    errors = []

    def work(part):
        try:
            for scan in part:
                loc.localize(*scan.laser, odometry=scan.odometry)
        except Exception as e:  # noqa: BLE001
            errors.append(e)

    threads = [threading.Thread(target=work, args=(scans[i::4],)) for i in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert not errors and loc.stats["scans"] == 40


def test_bad_input(intel, data, tmp_path):
    log, _, yaml = intel
    m = mm.read_map(yaml)
    with pytest.raises(ValueError, match="outside the map"):
        mm.run_localize2d(log, m, frames=[300], initial_pose=(1e300, 0, 0))
    with pytest.raises(ValueError, match="yaw"):
        mm.Localizer2D(m).set_initial_pose((0, 0, 1e30))
    with pytest.raises(ValueError, match="nope"):
        mm.Localizer2D(m, parameters={"nope": 1})
    with pytest.raises(ValueError, match="global_min_score"):
        mm.Localizer2D(m, parameters={"global_min_score": 2.0})
    with pytest.raises(TypeError):
        mm.Localizer2D(m, parameters={"max_range": True})
    with pytest.raises(TypeError):
        mm.Localizer2D(42)
    with pytest.raises(ValueError, match="empty"):
        mm.run_localize2d(log, m, frames=[])
    with pytest.raises(ValueError, match="out of range"):
        mm.run_localize2d(log, m, frames=[10**7])
    with pytest.raises(ValueError):
        mm.Localizer2D(m).localize([0.0, 0.1], [1.0])
    with pytest.raises(ValueError, match="no beams"):
        mm.Localizer2D(m).localize([], [])
    with pytest.raises(mm.InputError, match="nowhere"):
        mm.read_map(tmp_path / "nowhere.yaml")
    kitti = data / "kitti_odometry_00"
    if kitti.is_dir():
        with pytest.raises(mm.InputError, match="2D laser scans"):
            mm.run_localize2d(kitti, m)
    with pytest.raises(RuntimeError, match="stop"):

        def stop(done, total):
            raise RuntimeError("stop")

        mm.run_localize2d(log, m, frames=range(300, 400), progress=stop)
