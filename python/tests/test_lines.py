"""metricmap.split_and_merge against `metricmap lines` on the bundled URG-04LX log."""

import json
import subprocess

import numpy as np
import pytest

import metricmap as mm

LOG = "breezyslam_mines_urg04lx/exp2.dat"


@pytest.fixture(scope="module")
def scans(data):
    return mm.read_scan_log(str(data / LOG), preset="urg04lx-mines")


@pytest.mark.parametrize(
    "scan,flags,kwargs",
    [
        (100, [], {}),
        (250, ["--distance-threshold", "0.1", "--min-points", "8", "--max-gap", "0.3"],
         {"distance_threshold": 0.1, "min_points": 8, "max_gap": 0.3}),
        (40, ["--chi2", "6.63"], {"chi2": 6.63}),
    ],
)
def test_segments_equal_the_cli(cli, data, scans, scan, flags, kwargs):
    out = subprocess.run(
        [cli, "lines", str(data / LOG), "--preset", "urg04lx-mines", "--scan", str(scan), "--format", "json", *flags],
        check=True,
        capture_output=True,
        text=True,
    ).stdout
    ref = json.loads(out)["scans"][0]["segments"]
    angles, ranges = scans[scan]
    seg = mm.split_and_merge(angles, ranges, **kwargs)
    assert len(ref) > 0 and len(seg["r"]) == len(ref)
    np.testing.assert_array_equal(seg["start"], [s["start"] for s in ref])
    np.testing.assert_array_equal(seg["end"], [s["end"] for s in ref])
    np.testing.assert_array_equal(seg["first_index"], [s["first_index"] for s in ref])
    np.testing.assert_array_equal(seg["last_index"], [s["last_index"] for s in ref])
    np.testing.assert_array_equal(seg["points"], [s["points"] for s in ref])
    np.testing.assert_array_equal(seg["r"], [s["fit"]["r"] for s in ref])
    np.testing.assert_array_equal(seg["alpha"], [s["fit"]["alpha"] for s in ref])
    np.testing.assert_array_equal(seg["cov"], [s["fit"]["cov"] for s in ref])
    for k, m in enumerate(seg["members"]):
        assert m[0] == seg["first_index"][k] and m[-1] == seg["last_index"][k]


def test_fits_are_least_squares_lines(scans):
    # Independent check: every member point lies near its line x cos a + y sin a = r.
    angles, ranges = scans[100]
    seg = mm.split_and_merge(angles, ranges)
    for k, m in enumerate(seg["members"]):
        x = ranges[m] * np.cos(angles[m])
        y = ranges[m] * np.sin(angles[m])
        d = x * np.cos(seg["alpha"][k]) + y * np.sin(seg["alpha"][k]) - seg["r"][k]
        assert np.abs(d).max() < 0.1 and abs(d.mean()) < 1e-4


def test_bad_scans():
    with pytest.raises(ValueError):
        mm.split_and_merge([0.0], [1.0, 2.0])
    with pytest.raises(ValueError):
        mm.split_and_merge([0.0, np.nan], [1.0, 2.0])
    with pytest.raises(ValueError):
        mm.split_and_merge([0.0, 0.1], [1.0, 2.0], distance_threshold=-1)
    with pytest.raises(ValueError):
        mm.split_and_merge([0.0, 0.1], [1.0, 2.0], purge="sometimes")
    empty = mm.split_and_merge([], [])
    assert len(empty["r"]) == 0
