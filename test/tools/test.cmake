# SPDX-License-Identifier: BSD-3-Clause
# The CLI's helpers live in tools/, not in a library: the ones under test are compiled into this binary.
target_sources(${target} PRIVATE ${PROJECT_SOURCE_DIR}/tools/progress.cpp)
target_include_directories(${target} PRIVATE ${PROJECT_SOURCE_DIR}/tools)
