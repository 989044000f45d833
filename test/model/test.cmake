# SPDX-License-Identifier: BSD-3-Clause
# The model-file tests run an independent HDF5 writer/reader (h5py) with Debian's Python.
target_compile_definitions(${target} PRIVATE
  MORPHREG_STATISMO_FIXTURE="${CMAKE_CURRENT_SOURCE_DIR}/model/statismo_fixture.py"
  MORPHREG_SYSTEM_PYTHON="/usr/bin/python3")
