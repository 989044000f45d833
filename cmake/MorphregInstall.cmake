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

# pkg-config: morphreg-core.pc (the core library) and morphreg.pc (every component), in the PCL way (Debian's PCL
# ships pcl_<module>.pc). The prefix is found from the .pc file's own folder, so an unpacked package works anywhere.
set(MORPHREG_PKGCONFIG_DIR "${CMAKE_INSTALL_LIBDIR}/pkgconfig")
file(RELATIVE_PATH MORPHREG_PC_TO_PREFIX "/prefix/${MORPHREG_PKGCONFIG_DIR}" "/prefix")
foreach(pc morphreg-core morphreg)
  configure_file(cmake/${pc}.pc.in "${CMAKE_CURRENT_BINARY_DIR}/${pc}.pc" @ONLY)
  install(FILES "${CMAKE_CURRENT_BINARY_DIR}/${pc}.pc" DESTINATION ${MORPHREG_PKGCONFIG_DIR})
endforeach()
install(FILES LICENSE CITATION.cff CHANGELOG.md DESTINATION ${CMAKE_INSTALL_DOCDIR})

# `cpack -G DEB` in the build folder: one .deb with the libraries, headers, CMake package, pkg-config files, the
# command line and the Python module, installed under /usr. Its runtime dependencies come from dpkg-shlibdeps (the
# packages of every library the binaries load); the headers and the CMake package need the development packages
# below, and the Python module its interpreter's version and numpy.
set(CPACK_PACKAGE_NAME morphreg)
set(CPACK_PACKAGE_VENDOR "the morphreg authors")
set(CPACK_PACKAGE_CONTACT "the morphreg authors")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_RESOURCE_FILE_LICENSE "${PROJECT_SOURCE_DIR}/LICENSE")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS_PRIVATE_DIRS "${CMAKE_INSTALL_LIBDIR}")
set(MORPHREG_DEB_DEPENDS "libpcl-dev (>= 1.13)" "libeigen3-dev (>= 3.4)" "nlohmann-json3-dev (>= 3)")
if(TARGET morphreg_python)
  math(EXPR MORPHREG_PYTHON_NEXT_MINOR "${Python3_VERSION_MINOR} + 1")
  list(APPEND MORPHREG_DEB_DEPENDS "python3 (>= ${Python3_VERSION_MAJOR}.${Python3_VERSION_MINOR})"
       "python3 (<< ${Python3_VERSION_MAJOR}.${MORPHREG_PYTHON_NEXT_MINOR})" "python3-numpy")
endif()
list(JOIN MORPHREG_DEB_DEPENDS ", " CPACK_DEBIAN_PACKAGE_DEPENDS)
include(CPack)
