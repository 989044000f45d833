# SPDX-License-Identifier: BSD-3-Clause
set(MORPHREG_CMAKE_DIR "${CMAKE_INSTALL_LIBDIR}/cmake/morphreg")

# morphreg_add_component(<name> FOLDERS <src folders> [PUBLIC <deps>] [PRIVATE <deps>]): the shared library
# libmorphreg_<name>, morphreg::<name>, built from every src/<folder>/*.cpp (globbed, so new files need no edit),
# installed with its own export file so find_package(morphreg COMPONENTS <name>) loads only what it needs.
function(morphreg_add_component name)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "" "FOLDERS;PUBLIC;PRIVATE")
  set(sources "")
  foreach(folder ${arg_FOLDERS})
    file(GLOB folder_sources CONFIGURE_DEPENDS "${PROJECT_SOURCE_DIR}/src/${folder}/*.cpp")
    list(APPEND sources ${folder_sources})
  endforeach()
  set(target morphreg_${name})
  add_library(${target} SHARED ${sources})
  add_library(morphreg::${name} ALIAS ${target})
  # Installed, each component finds the ones it needs next to itself.
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${name} INSTALL_RPATH "$ORIGIN"
    VERSION ${PROJECT_VERSION} SOVERSION ${PROJECT_VERSION_MAJOR})
  target_include_directories(${target} PUBLIC
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/include>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_link_libraries(${target} PUBLIC ${arg_PUBLIC} PRIVATE ${arg_PRIVATE})
  target_compile_options(${target} PRIVATE -Wall -Wextra)
  if(MORPHREG_NATIVE)
    target_compile_options(${target} PUBLIC -march=native)
  endif()
  # Each library is its own install component, so the Python wheel (setup.py) takes only the ones the module needs.
  install(TARGETS ${target} EXPORT morphreg_${name}Targets
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT ${name}
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT ${name}
    RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT ${name}
    INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  install(EXPORT morphreg_${name}Targets NAMESPACE morphreg:: DESTINATION ${MORPHREG_CMAKE_DIR})
endfunction()
