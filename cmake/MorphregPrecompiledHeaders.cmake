# SPDX-License-Identifier: BSD-3-Clause
# Precompiled headers: the Eigen and PCL headers most translation units include, parsed once per kind of target
# instead of once per file (a larger set, e.g. with Eigen/Dense or nlohmann/json, makes the files that do not use it
# slower to compile than they gain). GCC accepts a precompiled header only with the same code-generation flags and
# without macro definitions the compile lacks, so each is built by an object library of its own with the fewest
# definitions: morphreg_lib_pch (position-independent, core's public dependencies) for the four components,
# morphreg_exe_pch for tools, samples and benchmarks, and test/CMakeLists.txt's morphreg_test_pch (with GoogleTest).
option(MORPHREG_PRECOMPILED_HEADERS "Precompile the heavy Eigen and PCL headers" ON)
set(MORPHREG_PCH_HEADERS <Eigen/Core> <pcl/point_types.h> <pcl/point_cloud.h> <pcl/PolygonMesh.h> <map> <string>
    <vector>)

# morphreg_add_pch_target(<name> [POSITION_INDEPENDENT] LINKS <targets> [HEADERS <extra headers>]): an object
# library that only precompiles MORPHREG_PCH_HEADERS (and HEADERS) with the usage requirements of LINKS; for
# executables, a twin <name>_visualization also links morphreg::visualization, whose Qt dependency compiles with
# -fPIC (GCC refuses a header precompiled without it there).
function(morphreg_add_pch_target name)
  cmake_parse_arguments(PARSE_ARGV 1 arg "POSITION_INDEPENDENT" "" "LINKS;HEADERS")
  if(NOT MORPHREG_PRECOMPILED_HEADERS)
    return()
  endif()
  morphreg_add_pch_object_library(${name} "${arg_POSITION_INDEPENDENT}" "${arg_LINKS}" "${arg_HEADERS}")
  if(NOT arg_POSITION_INDEPENDENT)
    morphreg_add_pch_object_library(${name}_visualization OFF "${arg_LINKS};morphreg::visualization"
                                    "${arg_HEADERS}")
  endif()
endfunction()

function(morphreg_add_pch_object_library name position_independent links headers)
  set(source "${CMAKE_CURRENT_BINARY_DIR}/${name}.cpp")
  file(CONFIGURE OUTPUT "${source}" CONTENT "// Empty: ${name} only precompiles headers.\n")
  add_library(${name} OBJECT "${source}")
  set_target_properties(${name} PROPERTIES POSITION_INDEPENDENT_CODE ${position_independent})
  target_link_libraries(${name} PRIVATE ${links})
  target_precompile_headers(${name} PRIVATE ${MORPHREG_PCH_HEADERS} ${headers})
endfunction()

# morphreg_reuse_pch(<pch target> <targets>...): the targets compile with <pch target>'s precompiled headers (its
# _visualization twin for a target that links morphreg::visualization; call after target_link_libraries).
function(morphreg_reuse_pch pch_target)
  if(NOT MORPHREG_PRECOMPILED_HEADERS)
    return()
  endif()
  foreach(target ${ARGN})
    get_target_property(links ${target} LINK_LIBRARIES)
    if("morphreg::visualization" IN_LIST links AND TARGET ${pch_target}_visualization)
      target_precompile_headers(${target} REUSE_FROM ${pch_target}_visualization)
    else()
      target_precompile_headers(${target} REUSE_FROM ${pch_target})
    endif()
  endforeach()
endfunction()
