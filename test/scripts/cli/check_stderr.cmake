# SPDX-License-Identifier: BSD-3-Clause
# cmake -DARGS="program|arg|..." -DLOG=file [-DEXPECT_CODE=n] [-DREQUIRE=regex] [-DFORBID=regex] [-DEMPTY=ON]
#       -P check_stderr.cmake
# Runs the program with its stderr written to the file LOG (not a terminal, as in a batch job's log), expects exit
# code EXPECT_CODE (0 unless given) and checks the log: no '\r' (progress is redrawn only on a terminal), REQUIRE matches, no line matches
# FORBID, and with EMPTY nothing at all.
string(REPLACE "|" ";" command "${ARGS}")
execute_process(COMMAND ${command} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_FILE "${LOG}")
file(READ "${LOG}" err)
message("exit ${code}\nstdout: ${out}\nstderr (${LOG}): ${err}")
if(NOT EXPECT_CODE)
  set(EXPECT_CODE 0)
endif()
if(NOT code EQUAL EXPECT_CODE)
  message(FATAL_ERROR "expected exit code ${EXPECT_CODE}, got ${code}")
endif()
string(FIND "${err}" "\r" carriage_return)
if(NOT carriage_return EQUAL -1)
  message(FATAL_ERROR "stderr holds a carriage return at offset ${carriage_return}")
endif()
if(NOT REQUIRE STREQUAL "" AND NOT err MATCHES "${REQUIRE}")
  message(FATAL_ERROR "stderr does not match '${REQUIRE}'")
endif()
if(NOT FORBID STREQUAL "")
  string(REGEX MATCHALL "[^\n]*(${FORBID})[^\n]*" lines "${err}")
  list(LENGTH lines count)
  if(count GREATER 0)
    list(GET lines 0 first)
    message(FATAL_ERROR "${count} line(s) of stderr match '${FORBID}', the first: ${first}")
  endif()
endif()
if(EMPTY AND NOT err STREQUAL "")
  message(FATAL_ERROR "stderr is not empty")
endif()
