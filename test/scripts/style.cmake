# SPDX-License-Identifier: BSD-3-Clause
# StyleTest: the layout rules a reviewer would otherwise check by hand. No function in src/, include/ or python/src/ is longer
# than 60 lines (scripts/check_function_length.py), every C++ file is formatted by the project's .clang-format
# (clang-format from scripts/install-deps.sh), and every source file names its licence in an SPDX line
# (scripts/check_spdx.py looks at every file of the tree, so files added later are checked too). docs/cli.md is the
# built command line's help, as scripts/cli_reference.py writes it.
find_package(Python3 REQUIRED COMPONENTS Interpreter)
add_test(NAME StyleTest.SpdxLicenceLines
  COMMAND ${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/scripts/check_spdx.py ${PROJECT_SOURCE_DIR})
add_test(NAME StyleTest.SpdxCheckerFindsMissingLines
  COMMAND ${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/scripts/check_spdx.py --self-test)
add_test(NAME StyleTest.FunctionsAreAtMost60Lines
  COMMAND ${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/scripts/check_function_length.py --max-lines 60
          ${PROJECT_SOURCE_DIR}/src ${PROJECT_SOURCE_DIR}/include ${PROJECT_SOURCE_DIR}/python/src
  WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
# FixtureTest: every fixture a test requires is set up by some test, so ctest orders them (scripts/check_fixtures.py
# reads the suite from ctest itself).
add_test(NAME FixtureTest.EveryRequiredFixtureIsSetUp
  COMMAND ${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/scripts/check_fixtures.py ${CMAKE_BINARY_DIR})
add_test(NAME FixtureTest.CheckerFindsAnUnknownFixture
  COMMAND ${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/scripts/check_fixtures.py --self-test)
# FrontEndTest: tools/ stays an adapter over the library, at most 8 % of its lines (scripts/check_front_end_share.py).
add_test(NAME FrontEndTest.ToolsAreAtMost8PercentOfTheLibrary
  COMMAND ${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/scripts/check_front_end_share.py ${PROJECT_SOURCE_DIR}
          --max-percent 8)
add_test(NAME FrontEndTest.CheckerFindsALargeShare
  COMMAND ${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/scripts/check_front_end_share.py --self-test)
# LayerTest: the library's folders include only the folders docs/architecture.md's layer table allows them, and no
# public header names the shared data's path (scripts/check_layers.py).
add_test(NAME LayerTest.IncludesFollowTheLayers
  COMMAND ${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/scripts/check_layers.py ${PROJECT_SOURCE_DIR})
add_test(NAME LayerTest.CheckerFindsBrokenArrows
  COMMAND ${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/scripts/check_layers.py --self-test)

find_program(MORPHREG_CLANG_FORMAT NAMES clang-format clang-format-14)
if(NOT MORPHREG_CLANG_FORMAT)
  message(WARNING "morphreg: clang-format not found (scripts/install-deps.sh installs it); StyleTest.ClangFormat fails")
  set(MORPHREG_CLANG_FORMAT clang-format)
endif()
file(GLOB_RECURSE morphreg_formatted_files CONFIGURE_DEPENDS
  ${PROJECT_SOURCE_DIR}/include/*.h ${PROJECT_SOURCE_DIR}/include/*.hpp
  ${PROJECT_SOURCE_DIR}/src/*.h ${PROJECT_SOURCE_DIR}/src/*.cpp
  ${PROJECT_SOURCE_DIR}/tools/*.h ${PROJECT_SOURCE_DIR}/tools/*.cpp
  ${PROJECT_SOURCE_DIR}/samples/*.cpp ${PROJECT_SOURCE_DIR}/bench/*.cpp
  ${PROJECT_SOURCE_DIR}/fuzz/*.h ${PROJECT_SOURCE_DIR}/fuzz/*.cpp
  ${PROJECT_SOURCE_DIR}/python/src/*.h ${PROJECT_SOURCE_DIR}/python/src/*.cpp
  ${PROJECT_SOURCE_DIR}/test/*.h ${PROJECT_SOURCE_DIR}/test/*.cpp)
add_test(NAME StyleTest.ClangFormat
  COMMAND ${MORPHREG_CLANG_FORMAT} --dry-run --Werror ${morphreg_formatted_files}
  WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})

# The citation file and the changelog name the version of project() (setup.py reads it from there too).
add_test(NAME StyleTest.CitationAndChangelogNameTheVersion
  COMMAND ${Python3_EXECUTABLE} -c "import re, sys; v = re.escape(sys.argv[1]); \
assert re.search('^version: ' + v + '$', open(sys.argv[2]).read(), re.M), 'CITATION.cff: no version ' + sys.argv[1]; \
assert re.search('^## ' + v + ' ', open(sys.argv[3]).read(), re.M), 'CHANGELOG.md: no section ' + sys.argv[1]"
          ${PROJECT_VERSION} ${PROJECT_SOURCE_DIR}/CITATION.cff ${PROJECT_SOURCE_DIR}/CHANGELOG.md)

# docs/cli.md, the command line reference, is the help of the built executable; the test names the first line that
# differs and how to regenerate the file.
if(TARGET morphreg_cli)
  add_test(NAME StyleTest.CliReferenceIsCurrent
    COMMAND ${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/scripts/cli_reference.py --check $<TARGET_FILE:morphreg_cli>
            ${PROJECT_SOURCE_DIR}/docs/cli.md)
endif()
