# SPDX-License-Identifier: BSD-3-Clause
# cmake -DREPORT=file.json | -DARGS=morphreg|args... (JSON on stdout) -DCOMMAND=<subcommand> -DVERSION=<x.y.z>
#       [-DKEY=<key path, ;-separated>] -P check_provenance.cmake
# Checks that a JSON report of the command line carries the version that wrote it and the command line that made
# it: {"morphreg": {"version": VERSION, "command_line": ".../morphreg COMMAND ..."}}, or, with KEY, that object's
# fields at KEY (a model's metadata: morphreg_version and command_line).
if(DEFINED ARGS)
  string(REPLACE "|" ";" command "${ARGS}")
  execute_process(COMMAND ${command} RESULT_VARIABLE status OUTPUT_VARIABLE json ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${ARGS} exited ${status}:\n${err}")
  endif()
  set(REPORT "the output of ${ARGS}")
else()
  file(READ "${REPORT}" json)
endif()
if(DEFINED KEY)
  string(JSON version ERROR_VARIABLE missing GET "${json}" ${KEY} morphreg_version)
  string(JSON line ERROR_VARIABLE missing GET "${json}" ${KEY} command_line)
else()
  string(JSON version ERROR_VARIABLE missing GET "${json}" morphreg version)
  string(JSON line ERROR_VARIABLE missing GET "${json}" morphreg command_line)
endif()
if(missing)
  message(FATAL_ERROR "${REPORT}: no provenance: ${missing}")
endif()
if(NOT version STREQUAL VERSION)
  message(FATAL_ERROR "${REPORT}: written by version '${version}', expected '${VERSION}'")
endif()
if(NOT line MATCHES "(^|/)morphreg ${COMMAND}( |$)")
  message(FATAL_ERROR "${REPORT}: command line '${line}' is not a morphreg ${COMMAND} command")
endif()
message("${REPORT}: morphreg ${version}: ${line}")
