# SPDX-License-Identifier: BSD-3-Clause
# The Debian package made by `cpack -G DEB`, unpacked into a temporary root by dpkg -x and used from there.
# cmake -DMODE=build|pkgconfig|cli -DWORK_DIR=... [-DBUILD_DIR=... -DVERSION=...] [-DCONSUMER=core.cpp -DCXX=...]
#       -P deb.cmake
# build: the .deb of BUILD_DIR, its control fields (dependencies from dpkg-shlibdeps and the declared ones) and
#        contents checked, unpacked into WORK_DIR/root.
# pkgconfig: CONSUMER compiled by CXX with the flags of the unpacked morphreg-core.pc, run, and its morphreg library
#        checked to come from the root.
# cli: the unpacked command line runs and loads the unpacked libraries.
function(run_step)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err
                  WORKING_DIRECTORY "${WORK_DIR}")
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "step failed (${status}): ${ARGN}\n${out}\n${err}")
  endif()
  set(step_output "${out}" PARENT_SCOPE)
endfunction()

function(require text pattern what)
  if(NOT text MATCHES "${pattern}")
    message(FATAL_ERROR "${what}: no match for ${pattern} in:\n${text}")
  endif()
endfunction()

set(root "${WORK_DIR}/root")
if(MODE STREQUAL "build")
  file(REMOVE_RECURSE "${WORK_DIR}")
  file(MAKE_DIRECTORY "${WORK_DIR}")
  run_step(cpack -G DEB --config "${BUILD_DIR}/CPackConfig.cmake" -B "${WORK_DIR}")
  file(GLOB deb "${WORK_DIR}/morphreg_${VERSION}_*.deb")
  if(NOT deb)
    message(FATAL_ERROR "cpack made no morphreg_${VERSION}_*.deb in ${WORK_DIR}")
  endif()
  run_step(dpkg-deb --field "${deb}" Package Version Depends)
  message(STATUS "${deb}:\n${step_output}")
  # Found by dpkg-shlibdeps (PCL, VTK, HDF5, Embree) and declared (headers, CMake package, Python module).
  foreach(dependency "libpcl-io1\\.13" "libvtk9" "libhdf5" "libembree3" "libpcl-dev" "nlohmann-json3-dev"
                     "python3-numpy" "python3 \\(>= 3")
    require("${step_output}" "Depends:.*${dependency}" "${deb}'s Depends")
  endforeach()
  run_step(dpkg-deb --contents "${deb}")
  foreach(file "usr/bin/morphreg\n" "usr/include/morphreg/registration/morphable_icp.h"
               "usr/lib[^ ]*/libmorphreg_core\\.so\\.${VERSION}" "usr/lib[^ ]*/libmorphreg_visualization\\.so"
               "usr/lib[^ ]*/cmake/morphreg/morphregConfig\\.cmake" "usr/lib[^ ]*/pkgconfig/morphreg-core\\.pc"
               "usr/lib/python3/dist-packages/morphreg/_morphreg[^ ]*\\.so"
               "usr/lib/python3/dist-packages/morphreg-${VERSION}\\.dist-info/METADATA" "usr/share/doc/morphreg/LICENSE")
    require("${step_output}" "\\./${file}" "${deb}'s contents")
  endforeach()
  run_step(dpkg -x "${deb}" "${root}")
  message(STATUS "unpacked into ${root}")
elseif(MODE STREQUAL "pkgconfig")
  file(GLOB_RECURSE pc_files "${root}/*/morphreg-core.pc")
  get_filename_component(pc_dir "${pc_files}" DIRECTORY)
  set(pkg_config ${CMAKE_COMMAND} -E env "PKG_CONFIG_PATH=${pc_dir}" pkg-config)
  run_step(${pkg_config} --modversion morphreg)
  require("${step_output}" "^${VERSION}" "pkg-config --modversion morphreg")
  run_step(${pkg_config} --cflags --libs morphreg-core)
  separate_arguments(flags UNIX_COMMAND "${step_output}")
  run_step(${pkg_config} --variable=libdir morphreg-core)
  string(STRIP "${step_output}" libdir)
  run_step(${CXX} -std=c++17 -O1 "${CONSUMER}" -o "${WORK_DIR}/pkgconfig_consumer" ${flags} "-Wl,-rpath,${libdir}")
  run_step("${WORK_DIR}/pkgconfig_consumer")
  message(STATUS "pkg-config consumer: ${step_output}")
  run_step(ldd "${WORK_DIR}/pkgconfig_consumer")
  require("${step_output}" "libmorphreg_core\\.so\\.[0-9]+ => ${root}/" "the pkg-config consumer's libraries")
else()
  run_step("${root}/usr/bin/morphreg" --version)
  require("${step_output}" "morphreg ${VERSION}" "morphreg --version")
  run_step(ldd "${root}/usr/bin/morphreg")
  require("${step_output}" "libmorphreg_core\\.so\\.[0-9]+ => ${root}/" "the unpacked command line's libraries")
endif()
