# SPDX-License-Identifier: BSD-3-Clause
# The replay of the fuzz corpora and crash reproducers: the fuzz targets' sources (fuzz/) built into the normal
# suite, without libFuzzer; the photo target needs the photo component.
file(GLOB fuzz_target_sources CONFIGURE_DEPENDS "${PROJECT_SOURCE_DIR}/fuzz/*.cpp")
list(FILTER fuzz_target_sources EXCLUDE REGEX "libfuzzer_entry\\.cpp$")
target_sources(${target} PRIVATE ${fuzz_target_sources})
target_include_directories(${target} PRIVATE "${PROJECT_SOURCE_DIR}/fuzz")
target_link_libraries(${target} PRIVATE morphreg::photo ${MORPHREG_HDF5_TARGETS}) # model_contents writes HDF5
target_compile_definitions(${target} PRIVATE MORPHREG_FUZZ_DIR="${PROJECT_SOURCE_DIR}/fuzz")
