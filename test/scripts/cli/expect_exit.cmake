# cmake -DARGS="program|arg|..." -DEXPECT_CODE=n -DEXPECT_TEXT=text -P expect_exit.cmake
# Runs the program and passes when it exits with EXPECT_CODE and its stderr contains EXPECT_TEXT.
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
