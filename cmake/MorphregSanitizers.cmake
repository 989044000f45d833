# SPDX-License-Identifier: BSD-3-Clause
# Instrumented builds (scripts/check.sh, docs/FUZZING.md).
# MORPHREG_SANITIZE (e.g. "address,undefined"): every target compiled and linked with -fsanitize=<list>, for the
# sanitizer run of the whole test suite with GCC.
# MORPHREG_BUILD_FUZZERS: everything compiled with libFuzzer's coverage instrumentation, AddressSanitizer and
# UndefinedBehaviorSanitizer (any undefined behaviour aborts, so the fuzzer reports it); fuzz/ links the
# executables with libFuzzer itself. Needs Clang.
#
# Under AddressSanitizer Eigen stops trusting malloc's 16-byte alignment and allocates with its own offset blocks; PCL,
# built without it, then frees with free() the vectors of aligned points that morphreg's instantiations of the same
# templates allocated (a "bad-free" in PCLVisualizer::addPolygonMesh). x86-64 glibc and the sanitizers' malloc both
# return 16-byte aligned memory, so EIGEN_MALLOC_ALREADY_ALIGNED=1 keeps Eigen's allocations as PCL's.
set(MORPHREG_SANITIZE "" CACHE STRING "Sanitizers for every target, as -fsanitize=<list> (e.g. address,undefined)")
if(MORPHREG_SANITIZE OR MORPHREG_BUILD_FUZZERS)
  add_compile_definitions(EIGEN_MALLOC_ALREADY_ALIGNED=1)
endif()
if(MORPHREG_SANITIZE)
  add_compile_options(-fsanitize=${MORPHREG_SANITIZE} -fno-omit-frame-pointer)
  add_link_options(-fsanitize=${MORPHREG_SANITIZE})
endif()
if(MORPHREG_BUILD_FUZZERS)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "MORPHREG_BUILD_FUZZERS needs Clang (libFuzzer); configure with CXX=clang++ "
                        "(scripts/check.sh fuzz does)")
  endif()
  add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined
                      -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined)
endif()
