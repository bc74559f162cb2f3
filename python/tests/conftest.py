"""Shared fixtures: the repository's data/ folder and the `metricmap` command, when built."""

import os
import pathlib
import shutil

import pytest

REPO = pathlib.Path(__file__).resolve().parents[2]
DATA = REPO / "data"


def _cli():
    env = os.environ.get("METRICMAP_CLI")
    if env and pathlib.Path(env).is_file():
        return env
    for candidate in ("build/release/apps/metricmap", "build/python/apps/metricmap"):
        path = REPO / candidate
        if path.is_file():
            return str(path)
    return shutil.which("metricmap")


@pytest.fixture(scope="session")
def data():
    return DATA


@pytest.fixture(scope="session")
def cli():
    path = _cli()
    if path is None:
        pytest.skip("the metricmap command is not built (set METRICMAP_CLI)")
    return path


STUDY_FILES = ["ciencias000", "museo000", "poli000", "poli001"]
