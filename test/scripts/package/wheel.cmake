# SPDX-License-Identifier: BSD-3-Clause
# The Python package built by pip through pyproject.toml and setup.py, offline with Debian's setuptools and wheel.
# cmake -DMODE=wheel|install|source -DPYTHON=... -DSOURCE_DIR=... -DBUILD_DIR=... -DWORK_DIR=... -DVERSION=...
#       -DCHECK=check_module.py -P wheel.cmake
# wheel: `pip wheel` of the source tree into WORK_DIR/dist, reusing the configured BUILD_DIR (its objects are
#        built; setup.py builds the module's target there and installs its components), and its members checked.
# install: the wheel installed by pip into WORK_DIR/site and imported from there (CHECK).
# source: `pip install` of the source tree into WORK_DIR/source_site and imported from there.
function(run_step)
  string(TIMESTAMP start "%s")
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  string(TIMESTAMP end "%s")
  math(EXPR seconds "${end} - ${start}")
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "step failed (${status}): ${ARGN}\n${out}\n${err}")
  endif()
  message(STATUS "${seconds} s: ${ARGN}")
  set(step_output "${out}" PARENT_SCOPE)
endfunction()

# Offline: no build isolation (pip would fetch setuptools from PyPI), no dependencies fetched (numpy is Debian's).
set(pip ${CMAKE_COMMAND} -E env "MORPHREG_CMAKE_BUILD_DIR=${BUILD_DIR}"
        "MORPHREG_SETUPTOOLS_DIR=${WORK_DIR}/setuptools_${MODE}" PIP_NO_INDEX=1 PIP_DISABLE_PIP_VERSION_CHECK=1
        ${PYTHON} -m pip)
set(offline --no-build-isolation --no-deps)
if(MODE STREQUAL "wheel")
  file(REMOVE_RECURSE "${WORK_DIR}/dist" "${WORK_DIR}/setuptools_${MODE}")
  run_step(${pip} wheel ${offline} --wheel-dir "${WORK_DIR}/dist" "${SOURCE_DIR}")
  file(GLOB wheels "${WORK_DIR}/dist/morphreg-${VERSION}-*.whl")
  list(LENGTH wheels count)
  if(NOT count EQUAL 1)
    message(FATAL_ERROR "expected one morphreg-${VERSION} wheel in ${WORK_DIR}/dist, found: ${wheels}")
  endif()
  run_step(${PYTHON} -m zipfile --list ${wheels})
  foreach(member "morphreg/__init__\\.py " "morphreg/__init__\\.pyi " "morphreg/py\\.typed " "morphreg/_morphreg[^/ ]*\\.so "
                 "morphreg/libmorphreg_core\\.so\\.[0-9]+ " "morphreg/libmorphreg_photo\\.so\\.[0-9]+ "
                 "morphreg/libmorphreg_synthetic\\.so\\.[0-9]+ " "morphreg-${VERSION}\\.dist-info/METADATA ")
    if(NOT step_output MATCHES "${member}")
      message(FATAL_ERROR "${wheels} has no ${member}:\n${step_output}")
    endif()
  endforeach()
  message(STATUS "built ${wheels}")
elseif(MODE STREQUAL "install")
  file(GLOB wheels "${WORK_DIR}/dist/morphreg-${VERSION}-*.whl")
  file(REMOVE_RECURSE "${WORK_DIR}/site")
  run_step(${pip} install ${offline} --target "${WORK_DIR}/site" ${wheels})
  run_step(${PYTHON} -I "${CHECK}" "${WORK_DIR}/site" ${VERSION} "${WORK_DIR}/site/morphreg")
  message(STATUS "${step_output}")
else()
  file(REMOVE_RECURSE "${WORK_DIR}/source_site" "${WORK_DIR}/setuptools_${MODE}")
  run_step(${pip} install ${offline} --target "${WORK_DIR}/source_site" "${SOURCE_DIR}")
  run_step(${PYTHON} -I "${CHECK}" "${WORK_DIR}/source_site" ${VERSION} "${WORK_DIR}/source_site/morphreg")
  message(STATUS "${step_output}")
endif()
