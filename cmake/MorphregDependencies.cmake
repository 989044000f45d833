# SPDX-License-Identifier: BSD-3-Clause
# Dependencies, all from Debian's packages (scripts/install-deps.sh installs them).
# Quirk of Debian's PCL/VTK: MPI must be found before PCL, or VTK's MPI target is missing.
find_package(MPI QUIET COMPONENTS C)
find_package(PCL 1.13 REQUIRED COMPONENTS common io kdtree search registration visualization)
include(morphregPclTargets)
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(OpenMP REQUIRED COMPONENTS CXX)
find_package(HDF5 REQUIRED COMPONENTS C CXX)
find_package(nlohmann_json 3 REQUIRED)
find_package(tinyxml2 REQUIRED)
find_package(embree 3 REQUIRED) # ray casting for the scan resampler (libembree-dev)
find_package(PNG REQUIRED) # 16-bit depth images and PNG photos (libpng-dev)
find_package(JPEG REQUIRED) # JPEG photos (libjpeg-dev)

if(TARGET hdf5::hdf5_cpp)
  set(MORPHREG_HDF5_TARGETS hdf5::hdf5_cpp hdf5::hdf5)
else()
  add_library(morphreg_hdf5 INTERFACE)
  target_include_directories(morphreg_hdf5 INTERFACE ${HDF5_INCLUDE_DIRS})
  target_link_libraries(morphreg_hdf5 INTERFACE ${HDF5_CXX_LIBRARIES} ${HDF5_LIBRARIES})
  target_compile_definitions(morphreg_hdf5 INTERFACE ${HDF5_DEFINITIONS})
  set(MORPHREG_HDF5_TARGETS morphreg_hdf5)
endif()
