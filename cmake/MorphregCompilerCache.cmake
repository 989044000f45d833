# Use ccache automatically when it is installed: PCL's templates make rebuilds slow.
find_program(MORPHREG_CCACHE ccache)
if(MORPHREG_CCACHE AND NOT CMAKE_CXX_COMPILER_LAUNCHER)
  set(CMAKE_C_COMPILER_LAUNCHER "${MORPHREG_CCACHE}")
  set(CMAKE_CXX_COMPILER_LAUNCHER "${MORPHREG_CCACHE}")
  message(STATUS "morphreg: compiling through ${MORPHREG_CCACHE}")
endif()
