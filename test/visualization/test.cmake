# SPDX-License-Identifier: BSD-3-Clause
# The visualiser renders through X: run (and list) these tests under a virtual X server, one server at a time.
if(NOT MORPHREG_XVFB)
  message(FATAL_ERROR "the visualiser's tests need xvfb-run (Debian package xvfb; scripts/install-deps.sh)")
endif()
set_target_properties(${target} PROPERTIES CROSSCOMPILING_EMULATOR "${MORPHREG_XVFB}")
set(extra_test_properties RESOURCE_LOCK xvfb)
