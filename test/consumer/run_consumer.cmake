# SPDX-License-Identifier: BSD-3-Clause
# The installed package, in two modes.
# MODE=install: installs morphreg's build tree BUILD_DIR into PREFIX.
# MODE=consumer: configures and builds test/consumer (SOURCE_DIR) in WORK_DIR against PREFIX for COMPONENT (empty:
# the whole package), runs it (with RUN_PREFIX before it, e.g. xvfb-run, and RUN_ARGS after), and checks the
# libraries it loads (ldd): each of REQUIRE_LIBS must match one of them, none may match FORBID_LOADED, and its link
# command may match none of FORBID_LINKED.
function(run_step)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "step failed (${status}): ${ARGN}\n${out}\n${err}")
  endif()
  set(step_output "${out}" PARENT_SCOPE)
endfunction()

if(MODE STREQUAL "install")
  file(REMOVE_RECURSE "${PREFIX}")
  run_step(${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${PREFIX}")
  message(STATUS "installed into ${PREFIX}")
  return()
endif()

file(REMOVE_RECURSE "${WORK_DIR}")
run_step(${CMAKE_COMMAND} -S "${SOURCE_DIR}" -B "${WORK_DIR}" -DCMAKE_BUILD_TYPE=Release
         "-DCMAKE_PREFIX_PATH=${PREFIX}" "-DMORPHREG_COMPONENT=${COMPONENT}")
run_step(${CMAKE_COMMAND} --build "${WORK_DIR}" -j2)
run_step(${RUN_PREFIX} "${WORK_DIR}/consumer" ${RUN_ARGS})
message(STATUS "consumer (${COMPONENT}): ${step_output}")

run_step(ldd "${WORK_DIR}/consumer")
set(libraries "${step_output}")
file(READ "${WORK_DIR}/CMakeFiles/consumer.dir/link.txt" link_command)
foreach(pattern ${REQUIRE_LIBS})
  if(NOT libraries MATCHES "${pattern}")
    message(FATAL_ERROR "the ${COMPONENT} consumer does not load ${pattern}:\n${libraries}")
  endif()
endforeach()
foreach(pattern ${FORBID_LOADED})
  if(libraries MATCHES "${pattern}")
    message(FATAL_ERROR "the ${COMPONENT} consumer loads ${pattern} (${CMAKE_MATCH_0}):\n${libraries}")
  endif()
endforeach()
foreach(pattern ${FORBID_LINKED})
  if(link_command MATCHES "${pattern}")
    message(FATAL_ERROR "the ${COMPONENT} consumer links ${pattern} (${CMAKE_MATCH_0}):\n${link_command}")
  endif()
endforeach()
