# SPDX-License-Identifier: BSD-3-Clause
# The glTF versions of the real scans are written with test/support/glb_writer.h, which compresses with draco.
target_link_libraries(${target} PRIVATE draco::draco)
# The real-scan zoo's helper (scripts/real_scan_zoo.sh): poses scans, renders depth frames and scores fits.
add_executable(morphreg_zoo_tool ${CMAKE_CURRENT_SOURCE_DIR}/real_scans/zoo/zoo_tool.cpp)
target_link_libraries(morphreg_zoo_tool PRIVATE morphreg::core morphreg::synthetic morphreg_test_support)
