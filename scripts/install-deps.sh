#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Installs the Debian packages morphreg needs to build, test and run its demo.
# Idempotent: packages already installed are left alone; apt-get update runs before any install.
# Must run as root (or with sudo available). Fails loudly when a package cannot be installed.
set -euo pipefail

PACKAGES=(
  cmake make g++ ccache pkg-config
  libpcl-dev            # PCL 1.13 with FLANN, VTK 9.1, Eigen 3.4, Boost
  libgtest-dev googletest libbenchmark-dev
  libhdf5-dev           # model files (statismo layout)
  nlohmann-json3-dev    # JSON reports and landmark files
  libcli11-dev          # the command line
  libtinyxml2-dev       # MeshLab .pp landmark files
  libembree-dev         # Intel Embree: the scan resampler's ray casting
  libtinygltf-dev       # glTF 2.0 / GLB scans and meshes (a shared library in Debian, with its header)
  libdraco-dev          # Draco-compressed glTF meshes (KHR_draco_mesh_compression)
  libpng-dev libjpeg-dev  # PNG and JPEG images: photos, scan textures, 16-bit depth images (register --depth)
  xvfb xauth            # headless rendering for the visualiser and its tests
  python3 python3-h5py python3-numpy  # independent HDF5 writer used as a test fixture
  python3-dev pybind11-dev python3-pytest python3-open3d  # the Python module, its tests and its Open3D example
  python3-setuptools python3-wheel python3-pip  # pip wheel . / pip install . offline (pyproject.toml, setup.py)
  dpkg-dev file         # cpack -G DEB: dpkg-shlibdeps finds the package's dependencies, file its binaries
  clang-format          # the layout check (StyleTest.ClangFormat, .clang-format)
  doxygen               # the API reference (`docs` target) and its warning check (ctest doxygen_docs)
  slurmctld slurmd slurm-client munge  # a one-node Slurm for the job-array test (scripts/local_slurm.sh)
)

missing=()
for pkg in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$pkg")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#PACKAGES[@]} packages already installed"
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "install-deps: not root and no sudo; cannot install: ${missing[*]}" >&2; exit 1; }
  SUDO="sudo"
fi

echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update
if ! $SUDO apt-get install -y --no-install-recommends "${missing[@]}"; then
  echo "install-deps: FAILED to install: ${missing[*]}" >&2
  exit 1
fi
echo "install-deps: done"
