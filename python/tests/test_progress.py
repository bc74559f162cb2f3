"""Long calls report progress(done, total) and stop on Ctrl-C (or on an exception from the
callback) between scans: the results with a callback equal those without, and SIGINT 1.5 s into
run_slam2d over the whole Intel log raises KeyboardInterrupt within 0.5 s."""

import os
import pathlib
import signal
import subprocess
import sys
import time

import numpy as np
import pytest

import metricmap as mm

INTEL = ("radish_clf_raw", "intel.clf.bz2")


@pytest.fixture(scope="module")
def intel(data):
    return mm.open_scan_source(data.joinpath(*INTEL))


def recorder():
    calls = []
    return calls, lambda done, total: calls.append((done, total))


def check_calls(calls, total):
    assert calls and calls[-1] == (total, total)
    done = [d for d, _ in calls]
    assert all(t == total for _, t in calls) and done == sorted(done) and done[0] >= 1


def test_run_slam2d_progress(intel):
    calls, progress = recorder()
    slam = mm.run_slam2d(intel, frames=range(80), progress=progress)
    check_calls(calls, 80)
    np.testing.assert_array_equal(slam.trajectory, mm.run_slam2d(intel, frames=range(80)).trajectory)


def test_run_odometry_progress(intel):
    calls, progress = recorder()
    run = mm.run_odometry(intel, frames=range(30), progress=progress)
    check_calls(calls, 30)
    np.testing.assert_array_equal(run["poses"], mm.run_odometry(intel, frames=range(30))["poses"])


def test_sequence_mapper_progress_and_a_stopped_build(intel):
    poses = mm.run_odometry(intel, frames=range(20))["sensor_poses"]
    mapper = mm.SequenceMapper(intel)
    calls, progress = recorder()
    mapper.build(poses, frames=range(20), progress=progress)
    check_calls(calls, 20)
    assert mapper.occupied_cells() > 0

    class Stop(Exception):
        pass

    def stop(done, total):
        raise Stop(done)

    with pytest.raises(Stop):
        mapper.build(poses, frames=range(20), progress=stop)
    with pytest.raises(ValueError, match="no map"):  # a stopped build leaves no maps
        mapper.occupied_cells()


def test_progress_must_be_callable(intel):
    with pytest.raises(TypeError, match="progress"):
        mm.run_slam2d(intel, frames=range(3), progress=5)
    with pytest.raises(TypeError):  # keyword-only
        mm.run_slam2d(intel, range(3), None, True, print)


CHILD = r"""
import signal, sys, time
# Ctrl-C as a fresh interpreter in a terminal has it: a process started from a test run may
# inherit SIGINT blocked or ignored.
signal.pthread_sigmask(signal.SIG_UNBLOCK, {signal.SIGINT})
signal.signal(signal.SIGINT, signal.default_int_handler)
import metricmap as mm
src = mm.open_scan_source(sys.argv[1])
print("start", flush=True)
t0 = time.monotonic()
try:
    mm.run_slam2d(src)
    print("finished", time.monotonic() - t0, flush=True)
except KeyboardInterrupt:
    print("interrupted", time.monotonic(), time.monotonic() - t0, flush=True)
"""


def interrupted_run(data):
    """Ctrl-C 1.5 s into run_slam2d over the whole Intel log, in a child: its last line and the
    time the signal was sent."""
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(p for p in sys.path if p))
    child = subprocess.Popen([sys.executable, "-c", CHILD, str(data.joinpath(*INTEL))],
                             stdout=subprocess.PIPE, text=True, env=env)
    try:
        assert child.stdout.readline().strip() == "start"
        time.sleep(1.5)
        sent = time.monotonic()
        child.send_signal(signal.SIGINT)
        line = child.stdout.readline().split()
        child.wait(timeout=120)
    finally:
        child.kill()
    return line, sent


def test_ctrl_c_stops_run_slam2d_within_half_a_second(data):
    line, sent = interrupted_run(data)
    if line[0] != "interrupted":  # a machine busy enough to delay the child: once more
        line, sent = interrupted_run(data)
    assert line[0] == "interrupted", line  # the whole log takes far longer than 1.5 s
    assert float(line[1]) - sent < 0.5
    assert float(line[2]) > 1.4
