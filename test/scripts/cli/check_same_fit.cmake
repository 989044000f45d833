# SPDX-License-Identifier: BSD-3-Clause
# cmake -DPROGRAM=morphreg -DMODEL=model.h5 -DORIGINAL=scan -DVERSIONS="a.glb|b.glb|..." -DOUT=folder
#       -P check_same_fit.cmake
# Registers ORIGINAL and each of VERSIONS (the same scan in other files) at register's defaults and passes when every
# version ends as the original does (the same exit code, 0 or 4: a fit that fails its checks is still a fit) with the
# same iteration count, termination, scan-to-model RMS to the printed precision and correspondence count. A capped
# run (MORPHREG_TEST_SAMPLES, the sanitizer run) stops every fit after 10 iterations: each version is read as fully,
# and must end as the original does after as many iterations.
file(MAKE_DIRECTORY "${OUT}")
set(iterations "")
if(DEFINED ENV{MORPHREG_TEST_SAMPLES})
  set(iterations --iterations 10)
  message("[ samples ] MORPHREG_TEST_SAMPLES=$ENV{MORPHREG_TEST_SAMPLES}: every fit stops after 10 iterations")
endif()
function(register_scan scan name summary_var)
  execute_process(COMMAND ${PROGRAM} register --scan ${scan} --model ${MODEL} --quiet ${iterations}
                          --out ${OUT}/${name}.ply
                  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message("${name}: exit ${code}\n${out}${err}")
  if(NOT code MATCHES "^[04]$")
    message(FATAL_ERROR "${scan}: register exited ${code}, expected a fit (0, or 4 for a fit that failed its checks)")
  endif()
  if(NOT out MATCHES "in ([0-9]+ iterations \\([a-z_]+), [^)]+\\): (scan-to-model RMS [0-9.e+-]+ mm over [0-9]+ correspondences)")
    message(FATAL_ERROR "${scan}: register printed no summary line")
  endif()
  set(${summary_var} "exit ${code}, ${CMAKE_MATCH_1}), ${CMAKE_MATCH_2}" PARENT_SCOPE)
endfunction()

register_scan(${ORIGINAL} original expected)
string(REPLACE "|" ";" versions "${VERSIONS}")
set(failures "")
foreach(version IN LISTS versions)
  get_filename_component(name ${version} NAME_WE)
  register_scan(${version} ${name} actual)
  message("${name}: ${actual}")
  if(NOT actual STREQUAL expected)
    list(APPEND failures "${version}: ${actual}")
  endif()
endforeach()
message("original ${ORIGINAL}: ${expected}")
if(failures)
  list(JOIN failures "\n  " text)
  message(FATAL_ERROR "these versions fit differently from the original (${expected}):\n  ${text}")
endif()
