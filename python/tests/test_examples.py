"""Every script of examples/python runs and says what it made."""

import os
import subprocess
import sys

import pytest

from conftest import REPO

EXAMPLES = REPO / "examples" / "python"


def run(script, *args, cwd):
    env = dict(os.environ, MPLBACKEND="Agg")
    return subprocess.run(
        [sys.executable, str(EXAMPLES / script), *map(str, args)],
        check=True, capture_output=True, text=True, cwd=cwd, env=env, timeout=600,
    )


def test_study_table(tmp_path):
    out = run("study_table.py", cwd=tmp_path).stdout
    # the README's first row, figure for figure
    assert "| ciencias000 | 1.0 / 1.0 / 100 | 79120 | 2477 | 23.75 | 2521 | 2206 | 1223 | 48.10 |" in out
    assert out.count("\n") == 2 + 4 * 3


def test_bin_points_kinect(tmp_path):
    pytest.importorskip("matplotlib")
    r = run("bin_points_kinect.py", tmp_path / "k.png", cwd=tmp_path)
    assert (tmp_path / "k.png").stat().st_size > 1000 and "points binned" in r.stdout


def test_kitti_map(tmp_path):
    pytest.importorskip("matplotlib")
    r = run("kitti_map.py", tmp_path / "m.png", cwd=tmp_path)
    assert (tmp_path / "m.png").stat().st_size > 1000 and "occupied cells" in r.stdout


def test_odometry_folder(tmp_path):
    r = run("odometry_folder.py", cwd=tmp_path)
    rows = [line.split() for line in r.stdout.splitlines()]
    assert len(rows) == len(list((REPO / "data/kitti_odometry_00/sequences/00/velodyne").glob("*.bin")))
    assert all(len(row) == 12 for row in rows)
    assert float(rows[-1][3]) > 1.0  # the car moved forward


def test_slam2d_log(tmp_path):
    pytest.importorskip("matplotlib")
    r = run("slam2d_log.py", REPO / "data/radish_clf_raw/intel.clf.bz2", 300, tmp_path / "s.png", cwd=tmp_path)
    assert (tmp_path / "s.png").stat().st_size > 1000 and (tmp_path / "s.pgm").is_file()
    assert "300 scans" in r.stdout and "loop closures" in r.stdout


def test_sequence_odometry(tmp_path):
    r = run("sequence_odometry.py", REPO / "data/kitti_odometry_00", tmp_path / "m.pgm", cwd=tmp_path)
    assert "kitti source: 6 scans" in r.stdout and "ATE rmse" in r.stdout
    assert (tmp_path / "m.pgm").is_file() and (tmp_path / "m.yaml").is_file()
