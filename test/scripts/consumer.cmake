# SPDX-License-Identifier: BSD-3-Clause
# PackageTest: morphreg is installed into a temporary prefix, then a tiny external project per component builds
# against it (find_package(morphreg COMPONENTS <c>), linking morphreg::<c> alone) and runs; one more uses the whole
# package (morphreg::morphreg). Only the visualization consumer may link VTK's rendering or pcl_visualization, or
# load VTK's OpenGL backend and X. (libvtkRenderingCore itself is loaded by every consumer: Debian's
# libvtkIOGeometry, which pcl_io needs for its mesh formats, depends on it.)
set(consumer_dir ${CMAKE_CURRENT_BINARY_DIR}/consumer)
set(consumer_script ${CMAKE_CURRENT_SOURCE_DIR}/consumer/run_consumer.cmake)
set(rendering_linked "vtkRendering" "vtkInteraction" "pcl_visualization")
set(rendering_loaded "libpcl_visualization" "libvtkRendering(OpenGL2|FreeType|Annotation|Context)" "libvtkInteraction"
    "libX11" "libGL")
add_test(NAME PackageTest.Install
  COMMAND ${CMAKE_COMMAND} -DMODE=install -DBUILD_DIR=${CMAKE_BINARY_DIR} -DPREFIX=${consumer_dir}/prefix
          -P ${consumer_script})
set_tests_properties(PackageTest.Install PROPERTIES FIXTURES_SETUP morphreg_installed TIMEOUT 300)
set_property(GLOBAL PROPERTY MORPHREG_TEST_INSTALL_PREFIX ${consumer_dir}/prefix) # python/tests imports from it

# package_consumer_test(<name> <component or ""> [REQUIRE_LIBS ...] [FORBID_LOADED ...] [FORBID_LINKED ...]
#                       [RUN_PREFIX ...] [RUN_ARGS ...]): see consumer/run_consumer.cmake.
function(package_consumer_test name component)
  set(lists REQUIRE_LIBS FORBID_LOADED FORBID_LINKED RUN_PREFIX RUN_ARGS)
  cmake_parse_arguments(PARSE_ARGV 2 arg "" "" "${lists}")
  set(definitions "-DCOMPONENT=${component}")
  foreach(list ${lists})
    string(REPLACE ";" "$<SEMICOLON>" escaped "${arg_${list}}")
    list(APPEND definitions "-D${list}=${escaped}")
  endforeach()
  add_test(NAME PackageTest.${name}
    COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${CMAKE_CURRENT_SOURCE_DIR}/consumer -DPREFIX=${consumer_dir}/prefix
            -DWORK_DIR=${consumer_dir}/${name} ${definitions} -P ${consumer_script})
  set_tests_properties(PackageTest.${name} PROPERTIES FIXTURES_REQUIRED morphreg_installed TIMEOUT 600)
endfunction()

package_consumer_test(CoreConsumer core REQUIRE_LIBS "libmorphreg_core"
  FORBID_LOADED ${rendering_loaded} "libmorphreg_(photo|synthetic|visualization)" FORBID_LINKED ${rendering_linked})
package_consumer_test(PhotoConsumer photo REQUIRE_LIBS "libmorphreg_photo"
  FORBID_LOADED ${rendering_loaded} "libmorphreg_(synthetic|visualization)" FORBID_LINKED ${rendering_linked})
package_consumer_test(SyntheticConsumer synthetic REQUIRE_LIBS "libmorphreg_synthetic"
  FORBID_LOADED ${rendering_loaded} "libmorphreg_visualization" FORBID_LINKED ${rendering_linked})
# The visualization consumer draws offscreen when a virtual X server is at hand (the suite's, test/CMakeLists.txt).
set(render_arguments "")
if(MORPHREG_XVFB)
  set(render_arguments RUN_PREFIX ${MORPHREG_XVFB} RUN_ARGS --render)
endif()
package_consumer_test(VisualizationConsumer visualization
  REQUIRE_LIBS "libmorphreg_visualization" "libvtkRenderingOpenGL2" FORBID_LOADED "libmorphreg_(photo|synthetic)"
  ${render_arguments})
set_tests_properties(PackageTest.VisualizationConsumer PROPERTIES RESOURCE_LOCK xvfb)
package_consumer_test(WholePackageConsumer "" REQUIRE_LIBS "libmorphreg_core" "libmorphreg_synthetic")
