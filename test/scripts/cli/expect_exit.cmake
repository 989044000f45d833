# SPDX-License-Identifier: BSD-3-Clause
# cmake -DARGS="program|arg|..." -DEXPECT_CODE=n -DEXPECT_TEXT=text [-DREPORT=file.json] -P expect_exit.cmake
# Runs the program and passes when it exits with EXPECT_CODE and its stderr contains EXPECT_TEXT; with REPORT, also
# when that JSON report was written and its "status" is "failed".
string(REPLACE "|" ";" command "${ARGS}")
execute_process(COMMAND ${command} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("exit ${code}\nstdout: ${out}\nstderr: ${err}")
if(NOT code STREQUAL "${EXPECT_CODE}")
  message(FATAL_ERROR "expected exit code ${EXPECT_CODE}, got ${code}")
endif()
string(FIND "${err}" "${EXPECT_TEXT}" found)
if(found EQUAL -1)
  message(FATAL_ERROR "stderr does not contain '${EXPECT_TEXT}'")
endif()
if(REPORT)
  file(READ "${REPORT}" json)
  string(JSON status GET "${json}" status)
  if(NOT status STREQUAL "failed")
    message(FATAL_ERROR "${REPORT}: status is '${status}', expected 'failed'")
  endif()
endif()
