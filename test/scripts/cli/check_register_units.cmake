# SPDX-License-Identifier: BSD-3-Clause
# A check of run_command.cmake (CHECKS) for `morphreg register` with -DUNITS=mm|cm|m|in -DDETECTION=auto|given:
# the report gives the scan's unit UNITS, found as DETECTION says, and stdout says the scan was rescaled to mm exactly
# when UNITS is not mm.
string(JSON units ERROR_VARIABLE missing GET "${json}" scan units)
string(JSON detection ERROR_VARIABLE missing GET "${json}" scan unit_detection)
string(JSON reason ERROR_VARIABLE missing GET "${json}" scan unit_reason)
if(NOT units STREQUAL "${UNITS}" OR NOT detection STREQUAL "${DETECTION}")
  fail("${REPORT}: scan units '${units}' (${detection}: ${reason}); expected '${UNITS}' (${DETECTION})")
endif()
string(FIND "${out}" "units: the scan's unit is ${UNITS} (" said)
string(FIND "${out}" "rescaled to mm" rescaled)
if(UNITS STREQUAL "mm" AND NOT rescaled EQUAL -1)
  fail("a scan in mm was rescaled")
elseif(NOT UNITS STREQUAL "mm" AND (said EQUAL -1 OR rescaled EQUAL -1))
  fail("stdout does not say the scan in ${UNITS} was rescaled to mm")
endif()
