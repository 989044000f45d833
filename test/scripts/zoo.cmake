# SPDX-License-Identifier: BSD-3-Clause
# RealScanZoo: scripts/real_scan_zoo.sh with one random pose per scan and unit and every depth frame, its targets
# checked (issue 31): every shared real scan at register's defaults exits 0 with status ok within its face median.
# Skipped without ../shared/data. Known misses: james's face-only capture seen by the simulated depth camera from
# 45 degrees (crop 5.5 mm and a failed check) and in profile (crop 3.2 mm, scene 7.2 mm), all against 2.0 mm; the
# one-view start (global_alignment.h) now finds the frontal crops of james and demoface (0.94 and 0.92 mm, 3.3 and
# 3.8 mm before it). The check fails when one of them meets its target, so that the list only shrinks.
if(NOT TARGET morphreg_cli OR NOT TARGET morphreg_zoo_tool)
  return()
endif()
morphreg_command_test(RealScanZoo TIMEOUT 1500
  REQUIRES_DATA ${MORPHREG_SHARED_DATA_DIR}/real_head_scans ${MORPHREG_SHARED_DATA_DIR}/ict_facekit/ict_head_pca_basis.npy
  OUTPUT "[0-9]+ of [0-9]+ cases within their targets"
  COMMAND ${PROJECT_SOURCE_DIR}/scripts/real_scan_zoo.sh --poses 1 --check --build ${CMAKE_BINARY_DIR}
          --out ${CMAKE_BINARY_DIR}/test/zoo --data ${MORPHREG_SHARED_DATA_DIR}
          --known-miss james_depth_oblique_crop --known-miss james_depth_profile_crop
          --known-miss james_depth_profile_scene)
set_tests_properties(RealScanZoo PROPERTIES RUN_SERIAL ON) # two registrations at once, one per core
