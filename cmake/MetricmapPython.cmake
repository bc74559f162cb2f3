# Python 3 (interpreter + extension-module headers) and pybind11 for python/ (the `metricmap`
# Python module). Sets METRICMAP_PYTHON_FOUND; finds nothing else and fails nothing: the option
# METRICMAP_BUILD_PYTHON defaults to what was found.
#
# The interpreter: -DPython_EXECUTABLE=... when given (setup.py passes the one running pip);
# otherwise Debian's /usr/bin/python3 when present — the python3 first on PATH may be another
# build (pyenv) without numpy or Debian's pybind11 — else whatever FindPython finds.
set(METRICMAP_PYTHON_FOUND OFF)
if(NOT DEFINED Python_EXECUTABLE AND EXISTS /usr/bin/python3)
  set(Python_EXECUTABLE /usr/bin/python3 CACHE FILEPATH "Python interpreter of the metricmap module")
endif()
find_package(Python 3.7 QUIET COMPONENTS Interpreter Development.Module)
if(Python_FOUND)
  find_package(pybind11 2.6 CONFIG QUIET)
  if(pybind11_FOUND)
    set(METRICMAP_PYTHON_FOUND ON)
  endif()
endif()
