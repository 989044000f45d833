# SPDX-License-Identifier: BSD-3-Clause
# PCL's imported targets pcl_io and pcl_2d (linked by pcl_features, linked by pcl_registration) link every VTK module
# PCL uses, rendering included, though those libraries need only VTK's data model, filters and readers. morphreg
# links trimmed copies, morphreg::pcl_<name>, without VTK's rendering, views, interaction, charts and Qt modules, so
# that only morphreg::visualization (through pcl_visualization) links VTK's rendering. Used by the build and by the
# installed package, after find_package(PCL).
set(_morphreg_vtk_rendering "^VTK::(Rendering|Views|Interaction|Charts|GUISupport)")
foreach(_morphreg_pcl 2d features io registration) # each after the ones it links
  if(TARGET morphreg::pcl_${_morphreg_pcl} OR NOT TARGET pcl_${_morphreg_pcl})
    continue()
  endif()
  string(TOUPPER "${_morphreg_pcl}" _morphreg_pcl_upper)
  get_target_property(_morphreg_links pcl_${_morphreg_pcl} INTERFACE_LINK_LIBRARIES)
  list(FILTER _morphreg_links EXCLUDE REGEX "${_morphreg_vtk_rendering}")
  list(TRANSFORM _morphreg_links REPLACE "^pcl_(2d|features)$" "morphreg::pcl_\\1")
  add_library(morphreg::pcl_${_morphreg_pcl} INTERFACE IMPORTED)
  set_target_properties(morphreg::pcl_${_morphreg_pcl} PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "$<TARGET_PROPERTY:pcl_${_morphreg_pcl},INTERFACE_INCLUDE_DIRECTORIES>"
    INTERFACE_COMPILE_DEFINITIONS "$<TARGET_PROPERTY:pcl_${_morphreg_pcl},INTERFACE_COMPILE_DEFINITIONS>"
    INTERFACE_LINK_LIBRARIES "${PCL_${_morphreg_pcl_upper}_LIBRARY};${_morphreg_links}")
endforeach()
unset(_morphreg_links)
unset(_morphreg_pcl_upper)
unset(_morphreg_vtk_rendering)
