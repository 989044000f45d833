# SPDX-License-Identifier: BSD-3-Clause
# morphreg_command_test(<test name> COMMAND <program> <args>...
#   [EXPECT_CODE n] [SKIP_CODE n] [OUTPUT regex...] [ERROR text...] [FORBID regex] [LOG file] [EMPTY_STDERR]
#   [MAXIMA "regex=>bound"...] [REPORT file [STATUS s] [REPORT_MATCH regex...]] [FILES file...] [ABSENT path...]
#   [KEEP file...] [CLEAN path...] [CHECKS script... [DEFINE var=value...]] [REQUIRES_DATA path...] [CASE_DIR dir [SETUP step...]]
#   [XVFB] [FIXTURES_REQUIRED fixture...] [FIXTURES_SETUP fixture...] [TIMEOUT seconds] [PROPERTIES ...])
# Declares a test run by test/scripts/cli/run_command.cmake, which checks the exit code and every outcome given
# (see that script). XVFB runs the command under the virtual X server (one at a time); a test whose REQUIRES_DATA
# is absent is reported skipped with the reason.
#
# morphreg_cli_test(<name> <the same, but COMMAND> ARGS <morphreg's arguments>...): `morphreg <arguments>` as
# CliTest.<name>; ARGS comes last.
#
# CMake splits lists only outside square brackets, so an argument with unbalanced brackets would swallow the
# arguments after it: such an argument is refused (write a literal bracket of a regular expression as part of a
# balanced pair, or match it with '.').
set(MORPHREG_TEST_SCRIPT_LISTS COMMAND OUTPUT ERROR MAXIMA REPORT_MATCH FILES ABSENT KEEP CLEAN CHECKS REQUIRES_DATA
    SETUP)
set(MORPHREG_TEST_SCRIPT_VALUES EXPECT_CODE SKIP_CODE FORBID LOG REPORT STATUS CASE_DIR)
set(MORPHREG_TEST_OTHER_LISTS DEFINE FIXTURES_REQUIRED FIXTURES_SETUP PROPERTIES)

function(morphreg_require_balanced_brackets name argument)
  string(REGEX MATCHALL "\\[" opening "${argument}")
  string(REGEX MATCHALL "\\]" closing "${argument}")
  list(LENGTH opening opening)
  list(LENGTH closing closing)
  if(NOT opening EQUAL closing)
    message(FATAL_ERROR "test ${name}: unbalanced square brackets in '${argument}'")
  endif()
endfunction()

function(morphreg_command_test name)
  math(EXPR last "${ARGC} - 1")
  foreach(i RANGE 1 ${last})
    morphreg_require_balanced_brackets(${name} "${ARGV${i}}")
  endforeach()
  cmake_parse_arguments(PARSE_ARGV 1 arg "EMPTY_STDERR;XVFB" "${MORPHREG_TEST_SCRIPT_VALUES};TIMEOUT"
                        "${MORPHREG_TEST_SCRIPT_LISTS};${MORPHREG_TEST_OTHER_LISTS}")
  morphreg_add_parsed_test(${name})
endfunction()

function(morphreg_cli_test name)
  math(EXPR last "${ARGC} - 1")
  foreach(i RANGE 1 ${last})
    morphreg_require_balanced_brackets(CliTest.${name} "${ARGV${i}}")
  endforeach()
  cmake_parse_arguments(PARSE_ARGV 1 arg "EMPTY_STDERR;XVFB" "${MORPHREG_TEST_SCRIPT_VALUES};TIMEOUT"
                        "${MORPHREG_TEST_SCRIPT_LISTS};${MORPHREG_TEST_OTHER_LISTS};ARGS")
  set(arg_COMMAND $<TARGET_FILE:morphreg_cli> ${arg_ARGS})
  morphreg_add_parsed_test(CliTest.${name})
endfunction()

# The test of the caller's parsed arguments (arg_*).
function(morphreg_add_parsed_test name)
  if(arg_XVFB AND NOT MORPHREG_XVFB)
    add_test(NAME ${name} COMMAND ${CMAKE_COMMAND} -E echo "SKIPPED: xvfb-run is not installed (scripts/install-deps.sh)")
    set_tests_properties(${name} PROPERTIES SKIP_REGULAR_EXPRESSION "SKIPPED: ")
    return()
  elseif(arg_XVFB)
    list(PREPEND arg_COMMAND ${MORPHREG_XVFB})
  endif()
  set(definitions "")
  foreach(definition IN LISTS arg_DEFINE)
    list(APPEND definitions "-D${definition}")
  endforeach()
  foreach(variable ${MORPHREG_TEST_SCRIPT_LISTS} ${MORPHREG_TEST_SCRIPT_VALUES} EMPTY_STDERR)
    if(NOT "${arg_${variable}}" STREQUAL "" AND NOT "${arg_${variable}}" STREQUAL "FALSE")
      string(REPLACE ";" "$<SEMICOLON>" escaped "${arg_${variable}}")
      list(APPEND definitions "-D${variable}=${escaped}")
    endif()
  endforeach()
  add_test(NAME ${name} COMMAND ${CMAKE_COMMAND} ${definitions}
                                -P ${PROJECT_SOURCE_DIR}/test/scripts/cli/run_command.cmake)
  if(NOT arg_TIMEOUT)
    set(arg_TIMEOUT 300)
  endif()
  math(EXPR timeout "${arg_TIMEOUT} * ${MORPHREG_TEST_TIMEOUT_FACTOR}")
  set_tests_properties(${name} PROPERTIES TIMEOUT ${timeout} SKIP_REGULAR_EXPRESSION "SKIPPED: " ${arg_PROPERTIES})
  # cmake_parse_arguments(PARSE_ARGV) keeps a quoted "a;b" as one value with an escaped semicolon, which ctest would
  # take for one fixture named "a;b": split it into the fixtures it lists.
  foreach(kind REQUIRED SETUP)
    if(arg_FIXTURES_${kind})
      string(REPLACE "\\;" ";" fixtures "${arg_FIXTURES_${kind}}")
      set_tests_properties(${name} PROPERTIES FIXTURES_${kind} "${fixtures}")
    endif()
  endforeach()
  if(arg_XVFB)
    set_tests_properties(${name} PROPERTIES RESOURCE_LOCK xvfb)
  endif()
endfunction()
