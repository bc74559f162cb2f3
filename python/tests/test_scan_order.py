"""One order for a 2D scan: every 2D entry point takes (angles, ranges), the order `Scan.laser`
and `read_scan_log` give, so `f(*scan.laser)` is the right call; the swapped call is refused."""

import numpy as np
import pytest

import metricmap as mm

INTEL = ("radish_clf_raw", "intel.clf.bz2")
SCANS = 300


@pytest.fixture(scope="module")
def intel(data):
    return mm.open_scan_source(data.joinpath(*INTEL))


def test_add_scan_of_scan_laser_equals_run_slam2d(intel):
    reference = mm.run_slam2d(intel, frames=range(SCANS))
    slam = mm.Slam2D(sensor_to_base=intel.info["sensor_to_base"])
    for k in range(SCANS):
        scan = intel[k]
        slam.add_scan(*scan.laser, odometry=scan.odometry, stamp=scan.stamp)
    slam.finish()
    assert slam.trajectory.shape == (SCANS, 3)
    np.testing.assert_array_equal(slam.trajectory, reference.trajectory)
    np.testing.assert_array_equal(slam.node_scans, reference.node_scans)
    assert slam.map()["occupied_cells"] == reference.map()["occupied_cells"]


def test_add_scan_keywords_equal_positional(intel):
    a, b = mm.Slam2D(), mm.Slam2D()
    for k in range(5):
        angles, ranges = intel[k].laser
        a.add_scan(*intel[k].laser, odometry=intel[k].odometry)
        b.add_scan(ranges=ranges, angles=angles, odometry=intel[k].odometry)
    np.testing.assert_array_equal(a.trajectory, b.trajectory)


def test_swapped_scan_is_refused(intel):
    angles, ranges = intel[0].laser
    assert np.nanmax(ranges) > 2 * np.pi  # a range in the angles' place breaks their bound
    with pytest.raises(ValueError, match="angles first"):
        mm.Slam2D().add_scan(ranges, angles)
    with pytest.raises(ValueError, match="angles first"):
        mm.split_and_merge(ranges, angles)
    with pytest.raises(TypeError):  # options are keyword-only
        mm.Slam2D().add_scan(angles, ranges, intel[0].odometry)


def segment_check(angles, ranges, seg, threshold):
    """Independent oracle (no merging): each segment's member beams, placed by r (cos a, sin a),
    in beam order, lie within the split threshold of the chord between its first and last."""
    assert len(seg["r"]) > 0
    for m in seg["members"]:
        assert np.all(np.diff(m) > 0) and np.all(np.isfinite(ranges[m]))
        p = np.stack([ranges[m] * np.cos(angles[m]), ranges[m] * np.sin(angles[m])], axis=1)
        u = (p[-1] - p[0]) / np.linalg.norm(p[-1] - p[0])
        d = (p[:, 0] - p[0, 0]) * u[1] - (p[:, 1] - p[0, 1]) * u[0]
        assert np.abs(d).max() <= threshold + 1e-6


@pytest.mark.parametrize("k", [0, 150, 299])
def test_split_and_merge_of_scan_laser(intel, k):
    angles, ranges = intel[k].laser
    seg = mm.split_and_merge(*intel[k].laser, distance_threshold=0.05, angle_threshold=0.0)
    segment_check(angles, ranges, seg, 0.05)
    by_name = mm.split_and_merge(ranges=ranges, angles=angles, angle_threshold=0.0)
    np.testing.assert_array_equal(seg["start"], by_name["start"])


def test_split_and_merge_of_read_scan_log(data):
    scans = mm.read_scan_log(data / "breezyslam_mines_urg04lx" / "exp2.dat", preset="urg04lx-mines")
    angles, ranges = scans[10]
    segment_check(angles, ranges, mm.split_and_merge(*scans[10], angle_threshold=0.0), 0.05)


def test_read_scan_log_equals_scan_laser(data, intel):
    scans = mm.read_scan_log(data.joinpath(*INTEL))
    for k in (0, 99):
        for got, want in zip(scans[k], intel[k].laser):
            np.testing.assert_array_equal(got, want)
