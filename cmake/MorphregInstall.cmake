# install() rules and the exported CMake package: find_package(morphreg) + morphreg::morphreg.
include(CMakePackageConfigHelpers)
set(MORPHREG_CMAKE_DIR "${CMAKE_INSTALL_LIBDIR}/cmake/morphreg")

install(TARGETS morphreg EXPORT morphregTargets
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY include/morphreg DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
if(TARGET morphreg_hdf5)
  install(TARGETS morphreg_hdf5 EXPORT morphregTargets)
endif()
install(EXPORT morphregTargets NAMESPACE morphreg:: DESTINATION ${MORPHREG_CMAKE_DIR})

configure_package_config_file(cmake/morphregConfig.cmake.in
  "${CMAKE_CURRENT_BINARY_DIR}/morphregConfig.cmake" INSTALL_DESTINATION ${MORPHREG_CMAKE_DIR})
write_basic_package_version_file("${CMAKE_CURRENT_BINARY_DIR}/morphregConfigVersion.cmake"
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMajorVersion)
install(FILES "${CMAKE_CURRENT_BINARY_DIR}/morphregConfig.cmake"
              "${CMAKE_CURRENT_BINARY_DIR}/morphregConfigVersion.cmake"
        DESTINATION ${MORPHREG_CMAKE_DIR})
