"""Builds the compiled part of the `metricmap` package with the project's CMake.

Metadata lives in pyproject.toml. `pip install --no-build-isolation .` runs build_ext below:
CMake configures the project with METRICMAP_BUILD_PYTHON=ON (tests and the command off) for the
interpreter running pip, builds the target `_metricmap` only and puts it where setuptools packs
the wheel. Environment:
  METRICMAP_PY_BUILD_DIR      the CMake build directory (default: build/pip in the source tree,
                              kept between installs so that a reinstall only relinks)
  CMAKE_BUILD_PARALLEL_LEVEL  compile jobs (default 2)
  METRICMAP_CMAKE_ARGS        extra CMake arguments, e.g. "-DMETRICMAP_NATIVE=ON"
"""

import os
import pathlib
import shlex
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).resolve().parent


class CMakeExtension(Extension):
    def __init__(self, name):
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        out_dir = pathlib.Path(self.get_ext_fullpath(ext.name)).resolve().parent
        build_dir = pathlib.Path(os.environ.get("METRICMAP_PY_BUILD_DIR", ROOT / "build" / "pip"))
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", "2")
        env = dict(os.environ)
        env.setdefault("CCACHE_BASEDIR", str(ROOT))  # cache hits across build directories
        configure = [
            "cmake",
            "-S", str(ROOT),
            "-B", str(build_dir),
            "-DCMAKE_BUILD_TYPE=Release",
            "-DMETRICMAP_BUILD_PYTHON=ON",
            "-DMETRICMAP_BUILD_TESTS=OFF",
            "-DMETRICMAP_BUILD_APPS=OFF",
            f"-DPython_EXECUTABLE={sys.executable}",
            f"-DMETRICMAP_PYTHON_OUTPUT_DIR={out_dir}",
        ] + shlex.split(os.environ.get("METRICMAP_CMAKE_ARGS", ""))
        subprocess.run(configure, check=True, env=env)
        subprocess.run(
            ["cmake", "--build", str(build_dir), "--target", "_metricmap", "-j", jobs], check=True, env=env
        )
        built = pathlib.Path(self.get_ext_fullpath(ext.name))
        if not built.is_file():
            raise RuntimeError(f"CMake did not produce {built} (extension suffix mismatch?)")


setup(ext_modules=[CMakeExtension("metricmap._metricmap")], cmdclass={"build_ext": CMakeBuild})
