# SPDX-License-Identifier: BSD-3-Clause
# CompileFailTest: wrong template arguments fail to compile with a plain message from morphreg (a static_assert),
# not deep inside PCL's templates. Each program has its own target, outside `all`, which only its test builds.
add_executable(morphable_icp_wrong_scalar EXCLUDE_FROM_ALL
  ${CMAKE_CURRENT_SOURCE_DIR}/scripts/compile_fail/morphable_icp_wrong_scalar.cpp)
target_link_libraries(morphable_icp_wrong_scalar PRIVATE morphreg::core)
add_test(NAME CompileFailTest.MorphableIcpWithAPointTypeAsScalar
  COMMAND ${CMAKE_COMMAND} --build ${CMAKE_BINARY_DIR} --target morphable_icp_wrong_scalar)
set_tests_properties(CompileFailTest.MorphableIcpWithAPointTypeAsScalar PROPERTIES
  PASS_REGULAR_EXPRESSION "the second template argument is the scalar \\(float or double\\), not a point type"
  FAIL_REGULAR_EXPRESSION "pcl-1\\.13/pcl/[^ :]*:[0-9]+:[0-9]+: error"
  TIMEOUT 300)
