# SPDX-License-Identifier: BSD-3-Clause
# cmake -DARGS="program|arg|..." -DREPORT=file.json -DUNITS=mm|cm|m|in -DDETECTION=auto|given
#       -P check_register_units.cmake
# Runs `morphreg register` and passes when the fit succeeds (exit 0, report status "ok") with the scan's unit UNITS,
# found as DETECTION says, in the report, and stdout says the scan was rescaled to mm exactly when UNITS is not mm.
string(REPLACE "|" ";" command "${ARGS}")
execute_process(COMMAND ${command} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("exit ${code}\nstdout: ${out}\nstderr: ${err}")
if(NOT code EQUAL 0)
  message(FATAL_ERROR "expected exit code 0, got ${code}")
endif()
file(READ "${REPORT}" json)
string(JSON status GET "${json}" status)
string(JSON units GET "${json}" scan units)
string(JSON detection GET "${json}" scan unit_detection)
string(JSON reason GET "${json}" scan unit_reason)
if(NOT status STREQUAL "ok" OR NOT units STREQUAL "${UNITS}" OR NOT detection STREQUAL "${DETECTION}")
  message(FATAL_ERROR "${REPORT}: status '${status}', scan units '${units}' (${detection}: ${reason}); expected "
                      "'ok', '${UNITS}' (${DETECTION})")
endif()
string(FIND "${out}" "units: the scan's unit is ${UNITS} (" said)
string(FIND "${out}" "rescaled to mm" rescaled)
if(UNITS STREQUAL "mm" AND NOT rescaled EQUAL -1)
  message(FATAL_ERROR "a scan in mm was rescaled")
elseif(NOT UNITS STREQUAL "mm" AND (said EQUAL -1 OR rescaled EQUAL -1))
  message(FATAL_ERROR "stdout does not say the scan in ${UNITS} was rescaled to mm")
endif()
message("${REPORT}: scan in ${units} (${detection}: ${reason})")
