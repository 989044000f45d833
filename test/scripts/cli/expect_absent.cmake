# SPDX-License-Identifier: BSD-3-Clause
# cmake -DPATHS="file|folder|..." -P expect_absent.cmake
# Fails if any of the paths exists: what a failed run must not leave behind.
string(REPLACE "|" ";" paths "${PATHS}")
foreach(path ${paths})
  if(EXISTS "${path}")
    message(FATAL_ERROR "${path} was left behind by a failed run")
  endif()
endforeach()
