# The visualiser renders through X: run (and list) these tests under a virtual X server, one server at a time.
find_program(XVFB_RUN xvfb-run REQUIRED)
set(emulator "${XVFB_RUN};-a;-s;-screen 0 1280x1024x24")
if(MORPHREG_SANITIZE MATCHES "address")
  # LeakSanitizer takes what Mesa's software GL driver still holds at exit for leaks once the driver is unloaded
  # (dlclose unmaps the globals pointing to it): preloaded, after the sanitizer runtime, it stays loaded.
  execute_process(COMMAND ${CMAKE_CXX_COMPILER} -print-file-name=libasan.so OUTPUT_VARIABLE asan_runtime
                  OUTPUT_STRIP_TRAILING_WHITESPACE)
  find_file(MORPHREG_MESA_SWRAST swrast_dri.so PATHS /usr/lib/${CMAKE_LIBRARY_ARCHITECTURE}/dri NO_DEFAULT_PATH)
  if(MORPHREG_MESA_SWRAST)
    list(APPEND emulator env "LD_PRELOAD=${asan_runtime} ${MORPHREG_MESA_SWRAST}")
  endif()
endif()
set_target_properties(${target} PROPERTIES CROSSCOMPILING_EMULATOR "${emulator}")
set(extra_test_properties RESOURCE_LOCK xvfb)
