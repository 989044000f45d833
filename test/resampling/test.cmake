# SPDX-License-Identifier: BSD-3-Clause
# The resampler's private search grid (src/resampling/point_grid.h) is tested directly.
target_include_directories(${target} PRIVATE "${PROJECT_SOURCE_DIR}/src")
