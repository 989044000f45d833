# SPDX-License-Identifier: BSD-3-Clause
# PackageTest: the packages a user installs, each built from this build tree, installed into a temporary prefix and
# used from there: the .deb of `cpack -G DEB`, unpacked by dpkg -x, with a CMake consumer of the
# `project(x LANGUAGES CXX)` kind, a pkg-config consumer and its command line (python/tests/CMakeLists.txt adds its
# Python module, the wheel and `pip install .`). The packages are made from this build folder, so their builds take
# turns (RESOURCE_LOCK morphreg_build_tree).
set(package_dir ${CMAKE_CURRENT_BINARY_DIR}/package)
set(package_scripts ${CMAKE_CURRENT_SOURCE_DIR}/scripts/package)

find_program(MORPHREG_DPKG dpkg)
if(NOT MORPHREG_DPKG)
  message(STATUS "morphreg: no dpkg: the .deb package tests are left out")
  return()
endif()
set(deb_dir ${package_dir}/deb)
add_test(NAME PackageTest.DebBuild
  COMMAND ${CMAKE_COMMAND} -DMODE=build -DBUILD_DIR=${CMAKE_BINARY_DIR} -DWORK_DIR=${deb_dir}
          -DVERSION=${PROJECT_VERSION} -P ${package_scripts}/deb.cmake)
set_tests_properties(PackageTest.DebBuild PROPERTIES FIXTURES_SETUP morphreg_deb RESOURCE_LOCK morphreg_build_tree
  TIMEOUT 900)
add_test(NAME PackageTest.DebCMakeConsumer
  COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${CMAKE_CURRENT_SOURCE_DIR}/consumer -DPREFIX=${deb_dir}/root/usr
          -DWORK_DIR=${deb_dir}/cmake_consumer -DCOMPONENT= "-DREQUIRE_LIBS=libmorphreg_core\\.so\\.[0-9]+ => ${deb_dir}/root/"
          -P ${CMAKE_CURRENT_SOURCE_DIR}/consumer/run_consumer.cmake)
add_test(NAME PackageTest.DebPkgConfigConsumer
  COMMAND ${CMAKE_COMMAND} -DMODE=pkgconfig -DWORK_DIR=${deb_dir} -DVERSION=${PROJECT_VERSION}
          -DCONSUMER=${CMAKE_CURRENT_SOURCE_DIR}/consumer/core.cpp -DCXX=${CMAKE_CXX_COMPILER}
          -P ${package_scripts}/deb.cmake)
add_test(NAME PackageTest.DebCommandLine
  COMMAND ${CMAKE_COMMAND} -DMODE=cli -DWORK_DIR=${deb_dir} -DVERSION=${PROJECT_VERSION} -P ${package_scripts}/deb.cmake)
set(deb_tests PackageTest.DebCMakeConsumer PackageTest.DebPkgConfigConsumer PackageTest.DebCommandLine)
set_property(GLOBAL PROPERTY MORPHREG_TEST_DEB_ROOT ${deb_dir}/root) # python/tests imports the unpacked module
set_tests_properties(${deb_tests} PROPERTIES FIXTURES_REQUIRED morphreg_deb TIMEOUT 600)
set_tests_properties(PackageTest.DebBuild ${deb_tests} PROPERTIES LABELS package)
