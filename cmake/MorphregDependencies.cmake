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
# glTF 2.0 / GLB input (libtinygltf-dev): Debian ships tinygltf's header and a shared library (TinyGLTF::TinyGLTF).
# Only the header is used: src/io/tiny_gltf_implementation.cpp compiles it with hidden symbols, because libdraco.so
# exports another build of tinygltf's symbols that would shadow the shared library's (src/io/tiny_gltf_hidden.h).
find_package(TinyGLTF 2.7 REQUIRED CONFIG)
set(MORPHREG_TINYGLTF_INCLUDE_DIRS $<TARGET_PROPERTY:TinyGLTF::TinyGLTF,INTERFACE_INCLUDE_DIRECTORIES>)
# Draco decoding for glTF's KHR_draco_mesh_compression (libdraco-dev): draco::draco, the shared library.
find_package(draco 1.5 REQUIRED CONFIG)

if(TARGET hdf5::hdf5_cpp)
  set(MORPHREG_HDF5_TARGETS hdf5::hdf5_cpp hdf5::hdf5)
else()
  add_library(morphreg_hdf5 INTERFACE)
  target_include_directories(morphreg_hdf5 INTERFACE ${HDF5_INCLUDE_DIRS})
  target_link_libraries(morphreg_hdf5 INTERFACE ${HDF5_CXX_LIBRARIES} ${HDF5_LIBRARIES})
  target_compile_definitions(morphreg_hdf5 INTERFACE ${HDF5_DEFINITIONS})
  set(MORPHREG_HDF5_TARGETS morphreg_hdf5)
endif()

find_package(PNG REQUIRED)  # images (photos, scan textures, 16-bit depth images): libpng-dev
find_package(JPEG REQUIRED) # and libjpeg-dev

# The file readers' libraries beyond PCL (core's io folder; the fuzz build links them too).
set(MORPHREG_IO_LIBRARIES tinyxml2::tinyxml2 draco::draco PNG::PNG JPEG::JPEG)

# Debian's interpreter (/usr/bin/python3) is preferred over others first on the PATH (pyenv, a venv): numpy, h5py,
# pytest and Open3D come from Debian's packages, for the Python module and the test scripts alike.
if(NOT DEFINED Python3_EXECUTABLE AND EXISTS /usr/bin/python3)
  set(Python3_EXECUTABLE /usr/bin/python3)
endif()
