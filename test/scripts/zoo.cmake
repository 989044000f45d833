# SPDX-License-Identifier: BSD-3-Clause
# RealScanZoo: scripts/real_scan_zoo.sh with one random pose per scan and unit and every depth frame, its targets
# checked (issue 31): every shared real scan at register's defaults exits 0 with status ok within its face median.
# Skipped without ../shared/data. Known misses (issue 31 item 1, a start for face-only captures seen from one side,
# is not built): the simulated depth crops of the face-only captures (james frontal 3.3 mm, oblique 6.6 mm and a
# failed check, profile 3.4 mm; demoface frontal 3.8 mm) and james's profile scene (7.2 mm), all against 2.0 mm. The
# check fails when one of them meets its target, so that the list only shrinks.
if(NOT TARGET morphreg_cli OR NOT TARGET morphreg_zoo_tool)
  return()
endif()
morphreg_command_test(RealScanZoo TIMEOUT 1500
  REQUIRES_DATA ${MORPHREG_SHARED_DATA_DIR}/real_head_scans ${MORPHREG_SHARED_DATA_DIR}/ict_facekit/ict_head_pca_basis.npy
  OUTPUT "[0-9]+ of [0-9]+ cases within their targets"
  COMMAND ${PROJECT_SOURCE_DIR}/scripts/real_scan_zoo.sh --poses 1 --check --build ${CMAKE_BINARY_DIR}
          --out ${CMAKE_BINARY_DIR}/test/zoo --data ${MORPHREG_SHARED_DATA_DIR}
          --known-miss james_depth_frontal_crop --known-miss james_depth_oblique_crop
          --known-miss james_depth_profile_crop --known-miss demoface_depth_frontal_crop
          --known-miss james_depth_profile_scene)
set_tests_properties(RealScanZoo PROPERTIES RUN_SERIAL ON) # two registrations at once, one per core
