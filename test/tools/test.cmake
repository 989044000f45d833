# SPDX-License-Identifier: BSD-3-Clause
# The CLI's helpers live in tools/, not in a library: the ones under test are compiled into this binary (the
# header-only ones, table_options.h, with CLI11).
find_package(CLI11 REQUIRED)
target_sources(${target} PRIVATE ${PROJECT_SOURCE_DIR}/tools/progress.cpp)
target_include_directories(${target} PRIVATE ${PROJECT_SOURCE_DIR}/tools)
target_link_libraries(${target} PRIVATE CLI11::CLI11)
