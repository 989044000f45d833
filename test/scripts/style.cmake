# StyleTest: the layout rules a reviewer would otherwise check by hand. No function in src/, include/ or python/src/ is longer
# than 60 lines (scripts/check_function_length.py), and every C++ file is formatted by the project's .clang-format
# (clang-format from scripts/install-deps.sh).
find_package(Python3 REQUIRED COMPONENTS Interpreter)
add_test(NAME StyleTest.FunctionsAreAtMost60Lines
  COMMAND ${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/scripts/check_function_length.py --max-lines 60
          ${PROJECT_SOURCE_DIR}/src ${PROJECT_SOURCE_DIR}/include ${PROJECT_SOURCE_DIR}/python/src
  WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})

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
