# SPDX-License-Identifier: BSD-3-Clause
# A check of run_command.cmake (CHECKS) with -DCHECKER=check_scan_colours -DMESH=mesh.ply -DSCAN_DIR=folder: the
# colours of the mesh the command wrote are the scan's (check_scan_colours, which says why when they are not). A mesh
# that was not written is already a failure (FILES).
if(EXISTS "${MESH}")
  execute_process(COMMAND ${CHECKER} ${MESH} ${SCAN_DIR} RESULT_VARIABLE check_code OUTPUT_VARIABLE check_out
                  ERROR_VARIABLE check_err)
  message("${CHECKER}: exit ${check_code}\n${check_out}${check_err}")
  if(NOT check_code EQUAL 0)
    fail("${MESH}: its colours are not the scan's (check_scan_colours exited ${check_code}: ${check_err})")
  endif()
endif()
