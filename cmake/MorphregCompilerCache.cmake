# SPDX-License-Identifier: BSD-3-Clause
# Use ccache automatically when it is installed: PCL's templates make rebuilds slow. ccache caches compiles that use
# the precompiled headers (cmake/MorphregPrecompiledHeaders.cmake) only with the pch_defines and time_macros
# sloppiness, set here for morphreg's compiles whatever the user's ccache configuration.
find_program(MORPHREG_CCACHE ccache)
find_program(MORPHREG_ENV env)
if(MORPHREG_CCACHE AND MORPHREG_ENV AND NOT CMAKE_CXX_COMPILER_LAUNCHER)
  set(CMAKE_C_COMPILER_LAUNCHER "${MORPHREG_CCACHE}")
  set(CMAKE_CXX_COMPILER_LAUNCHER "${MORPHREG_ENV};CCACHE_SLOPPINESS=pch_defines,time_macros;${MORPHREG_CCACHE}")
  message(STATUS "morphreg: compiling through ${MORPHREG_CCACHE}")
endif()
