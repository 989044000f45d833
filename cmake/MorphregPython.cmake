# SPDX-License-Identifier: BSD-3-Clause
# The Python module (python/), on by default when Python 3's headers and pybind11 are found (the interpreter is
# chosen in MorphregDependencies.cmake).
if(NOT MORPHREG_BUILD_PYTHON)
  return()
endif()
find_package(Python3 COMPONENTS Interpreter Development.Module Development.Embed)
find_package(pybind11 2.6 CONFIG QUIET)
if(Python3_FOUND AND pybind11_FOUND)
  message(STATUS "morphreg: building the Python module for ${Python3_EXECUTABLE} (pybind11 ${pybind11_VERSION})")
  add_subdirectory(python)
else()
  message(STATUS "morphreg: no Python module (needs python3-dev and pybind11-dev; scripts/install-deps.sh installs "
                 "them)")
endif()
