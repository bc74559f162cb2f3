"""The README's install: a venv with Debian's packages, `pip install --no-build-isolation .`
offline, then `import metricmap` from outside the source tree. Slow (a CMake build), so it runs
only when METRICMAP_TEST_PIP=1 (scripts/test sets it)."""

import os
import subprocess
import sys

import pytest

from conftest import REPO


@pytest.mark.skipif(os.environ.get("METRICMAP_TEST_PIP") != "1", reason="set METRICMAP_TEST_PIP=1")
def test_pip_install_in_a_venv(tmp_path):
    venv = tmp_path / "venv"
    base = "/usr/bin/python3" if os.path.exists("/usr/bin/python3") else sys.executable
    subprocess.run([base, "-m", "venv", "--system-site-packages", str(venv)], check=True)
    py = venv / "bin" / "python"
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "PYTHONHOME")}
    env.update(PIP_NO_INDEX="1", PIP_DISABLE_PIP_VERSION_CHECK="1")  # offline
    subprocess.run(
        [str(py), "-m", "pip", "install", "-q", "--no-build-isolation", str(REPO)],
        check=True, env=env, cwd=tmp_path, timeout=3600,
    )
    code = (
        "import metricmap, pathlib, numpy as np;"
        "f = pathlib.Path(metricmap.__file__);"
        "assert 'site-packages' in str(f), f;"
        "assert (f.parent / 'py.typed').exists() and (f.parent / '__init__.pyi').exists();"
        "g = metricmap.grid(np.random.default_rng(0).uniform(0, 4, (1000, 3)), 1.0);"
        "print(metricmap.__version__, g.statistics['total_cells'])"
    )
    out = subprocess.run([str(py), "-c", code], env=env, cwd=tmp_path, capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    assert out.stdout.split() == ["0.1.0", "64"]
