# SPDX-License-Identifier: BSD-3-Clause
# install() rules and the exported CMake package: find_package(morphreg [COMPONENTS core photo synthetic
# visualization]) defines morphreg::<component>; with no components, every one and morphreg::morphreg.
# The components' export files are written by morphreg_add_component (cmake/MorphregComponents.cmake).
include(CMakePackageConfigHelpers)

install(DIRECTORY include/morphreg DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
if(TARGET morphreg_hdf5)
  install(TARGETS morphreg_hdf5 EXPORT morphreg_coreTargets)
endif()
install(TARGETS morphreg EXPORT morphregTargets)
install(EXPORT morphregTargets NAMESPACE morphreg:: DESTINATION ${MORPHREG_CMAKE_DIR})

configure_package_config_file(cmake/morphregConfig.cmake.in
  "${CMAKE_CURRENT_BINARY_DIR}/morphregConfig.cmake" INSTALL_DESTINATION ${MORPHREG_CMAKE_DIR})
write_basic_package_version_file("${CMAKE_CURRENT_BINARY_DIR}/morphregConfigVersion.cmake"
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMajorVersion)
install(FILES "${CMAKE_CURRENT_BINARY_DIR}/morphregConfig.cmake"
              "${CMAKE_CURRENT_BINARY_DIR}/morphregConfigVersion.cmake"
              "${CMAKE_CURRENT_SOURCE_DIR}/cmake/morphregPclTargets.cmake"
        DESTINATION ${MORPHREG_CMAKE_DIR})
