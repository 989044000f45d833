# SPDX-License-Identifier: BSD-3-Clause
# The `docs` target: the Doxygen reference of the public headers, with docs/method.md as its main page, in
# <build>/docs/html. Doxygen fails on any warning (docs/Doxyfile.in), so the target and the `doxygen_docs` test
# fail on an undocumented public member, a missing \param or \return, or a broken reference.
# Skipped with a message when doxygen is not installed (Debian package `doxygen`).
find_package(Doxygen QUIET)
if(NOT DOXYGEN_FOUND)
  message(STATUS "morphreg: doxygen not found, no `docs` target")
  return()
endif()

set(MORPHREG_DOCS_OUTPUT_DIR "${CMAKE_CURRENT_BINARY_DIR}/docs")
configure_file("${CMAKE_CURRENT_SOURCE_DIR}/docs/Doxyfile.in" "${MORPHREG_DOCS_OUTPUT_DIR}/Doxyfile" @ONLY)
add_custom_target(docs
  COMMAND "${DOXYGEN_EXECUTABLE}" "${MORPHREG_DOCS_OUTPUT_DIR}/Doxyfile"
  WORKING_DIRECTORY "${MORPHREG_DOCS_OUTPUT_DIR}"
  COMMENT "Doxygen: ${MORPHREG_DOCS_OUTPUT_DIR}/html/index.html (warnings fail the run)"
  VERBATIM)
if(MORPHREG_BUILD_TESTS)
  add_test(NAME doxygen_docs COMMAND "${DOXYGEN_EXECUTABLE}" "${MORPHREG_DOCS_OUTPUT_DIR}/Doxyfile"
           WORKING_DIRECTORY "${MORPHREG_DOCS_OUTPUT_DIR}")
endif()
