# SPDX-License-Identifier: BSD-3-Clause
# cmake -DPROGRAM=morphreg -DCHECKER=check_unit_estimate -DMODEL=model.h5 -DORIGINAL=scan -DVERSION=scan.glb
#       -DTRUE_SCALE=mm_per_unit -DBOUND=mm -DOUT=folder
#       -DSAMPLE=index -P check_unit_estimate.cmake
# Registers ORIGINAL (mm) and VERSION (the same scan in an arbitrary unit, TRUE_SCALE mm per unit as read) at
# register's defaults; both must exit 0, and check_unit_estimate must find VERSION's unit estimated from the head and
# its fit the original's (see check_unit_estimate.cpp). SAMPLE is the scan's index among the suite's scans: a capped
# run (MORPHREG_TEST_SAMPLES, the sanitizer run) skips the scans past its cap.
if(DEFINED ENV{MORPHREG_TEST_SAMPLES} AND SAMPLE GREATER_EQUAL "$ENV{MORPHREG_TEST_SAMPLES}")
  message("SKIPPED: MORPHREG_TEST_SAMPLES=$ENV{MORPHREG_TEST_SAMPLES} runs the suite's first scans only; this is scan ${SAMPLE}")
  return()
endif()
file(MAKE_DIRECTORY "${OUT}")
foreach(case "original;${ORIGINAL}" "estimated;${VERSION}")
  list(GET case 0 name)
  list(GET case 1 scan)
  execute_process(COMMAND ${PROGRAM} register --scan ${scan} --model ${MODEL} --quiet --out ${OUT}/${name}.ply
                  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message("${name}: exit ${code}\n${out}${err}")
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "${scan}: register exited ${code}, expected 0")
  endif()
endforeach()
execute_process(COMMAND ${CHECKER} ${OUT}/original.ply ${OUT}/estimated.ply ${TRUE_SCALE} ${BOUND}
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT code EQUAL 0)
  message(FATAL_ERROR "${VERSION}: its estimated unit or its fit is not the original's")
endif()
