# Python bindings (python/, module `wattswath`, pybind11): finds the interpreter and pybind11 and
# sets WATTSWATH_PYTHON, ON by default when both are found (OFF skips the module and its tests).
# The module is a shared object, so python/CMakeLists.txt compiles the seven static libraries as
# position-independent code when it is ON.
#
# `python3` on PATH may be a pyenv shim whose interpreter has no development files or NumPy, so the
# Debian interpreter /usr/bin/python3 is preferred unless Python_EXECUTABLE is given.
if(WATTSWATH_SANITIZE OR WATTSWATH_FUZZ)
  set(_wattswath_python_default OFF)  # a sanitized module would need the ASan runtime preloaded
else()
  if(NOT DEFINED Python_EXECUTABLE AND EXISTS /usr/bin/python3)
    set(Python_EXECUTABLE /usr/bin/python3 CACHE FILEPATH "Python interpreter for the bindings")
  endif()
  find_package(Python 3.7 QUIET COMPONENTS Interpreter Development.Module)
  if(Python_FOUND)
    set(PYBIND11_FINDPYTHON ON)
    find_package(pybind11 2.6 CONFIG QUIET)
  endif()
  if(Python_FOUND AND pybind11_FOUND)
    set(_wattswath_python_default ON)
  else()
    set(_wattswath_python_default OFF)
  endif()
endif()
option(WATTSWATH_PYTHON "Build the Python bindings (python/, needs pybind11-dev)" ${_wattswath_python_default})

if(WATTSWATH_PYTHON)
  if(NOT (Python_FOUND AND pybind11_FOUND))
    message(FATAL_ERROR "WATTSWATH_PYTHON is ON but pybind11 (Debian pybind11-dev) or Python's "
      "development files (python3-dev) were not found for interpreter '${Python_EXECUTABLE}'; "
      "install them or configure with -DWATTSWATH_PYTHON=OFF")
  endif()
  message(STATUS "wattswath: Python bindings for ${Python_EXECUTABLE} (${Python_VERSION}), "
    "pybind11 ${pybind11_VERSION}")
else()
  message(STATUS "wattswath: no Python bindings (WATTSWATH_PYTHON is OFF; it is ON by default when "
    "pybind11-dev and python3-dev are found, which scripts/setup.sh installs)")
endif()
