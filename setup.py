# SPDX-License-Identifier: BSD-3-Clause
"""Builds the morphreg Python package through the project's CMake (pyproject.toml names setuptools as the backend).

The extension _morphreg and the morphreg libraries it links (core, photo, synthetic) are built by CMake and installed
into the package folder, where the extension finds them (its RPATH holds $ORIGIN); PCL, VTK and the other dependencies
come from the system (Debian's packages, scripts/install-deps.sh). The version is the one of CMakeLists.txt.

Environment:
  MORPHREG_CMAKE_BUILD_DIR  an existing, configured build folder of this source tree to build and install from (e.g.
                            build/, which the wheel then reuses); by default a folder of its own under build/pip
  MORPHREG_CMAKE_ARGS       more arguments for CMake's configure step (only for the folder of its own)
  MORPHREG_SETUPTOOLS_DIR   setuptools' own build and egg-info folder (default build/pip)
  CMAKE_BUILD_PARALLEL_LEVEL   parallel jobs (default 2)
"""
import glob
import os
import re
import shlex
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

SOURCE = os.path.dirname(os.path.abspath(__file__))
BUILD_BASE = os.environ.get("MORPHREG_SETUPTOOLS_DIR") or os.path.join("build", "pip")
LIBRARIES = ("core", "photo", "synthetic")  # the install components the module needs
os.makedirs(os.path.join(SOURCE, BUILD_BASE), exist_ok=True)  # setuptools' build and egg-info folder


def project_version():
    with open(os.path.join(SOURCE, "CMakeLists.txt")) as stream:
        return re.search(r"project\(morphreg VERSION ([0-9.]+)", stream.read()).group(1)


def run(command, **kwargs):
    print("setup.py: " + " ".join(shlex.quote(str(word)) for word in command), flush=True)
    subprocess.check_call(command, **kwargs)


class CMakeBuild(build_ext):
    """Configures (unless given a build folder), builds the module's target and installs its components into the
    package folder of the wheel."""

    def run(self):
        build_dir = os.environ.get("MORPHREG_CMAKE_BUILD_DIR") or os.path.abspath(os.path.join(self.build_temp,
                                                                                               "cmake"))
        if not os.path.exists(os.path.join(build_dir, "CMakeCache.txt")):
            self.configure(build_dir)
        env = dict(os.environ)
        env.setdefault("CMAKE_BUILD_PARALLEL_LEVEL", "2")
        run(["cmake", "--build", build_dir, "--target", "morphreg_python"], env=env)
        staging = os.path.abspath(os.path.join(self.build_temp, "staging"))
        shutil.rmtree(staging, ignore_errors=True)
        for component in ("python",) + LIBRARIES:
            run(["cmake", "--install", build_dir, "--prefix", staging, "--component", component])
        self.copy_into_package(staging, os.path.dirname(self.get_ext_fullpath("morphreg._morphreg")))

    def configure(self, build_dir):
        options = ["-DCMAKE_BUILD_TYPE=Release", "-DPython3_EXECUTABLE=" + sys.executable,
                   "-DMORPHREG_BUILD_PYTHON=ON", "-DMORPHREG_BUILD_TESTS=OFF", "-DMORPHREG_BUILD_BENCHMARKS=OFF",
                   "-DMORPHREG_BUILD_TOOLS=OFF", "-DMORPHREG_BUILD_SAMPLES=OFF"]
        options += shlex.split(os.environ.get("MORPHREG_CMAKE_ARGS", ""))
        run(["cmake", "-S", SOURCE, "-B", build_dir] + options)

    @staticmethod
    def copy_into_package(staging, package):
        """The extension and the package's files as installed, and each library under its soname (a wheel holds no
        symbolic links), all in the package folder."""
        os.makedirs(package, exist_ok=True)
        installed = glob.glob(os.path.join(staging, "**", "morphreg", "_morphreg*.so"), recursive=True)
        if len(installed) != 1:
            sys.exit(f"setup.py: expected one installed _morphreg module under {staging}, found {installed}")
        for name in os.listdir(os.path.dirname(installed[0])):
            shutil.copy2(os.path.join(os.path.dirname(installed[0]), name), package)
        for library in LIBRARIES:
            # libmorphreg_<library>.so.<major> (the soname) and .so.<version>: the shorter is the soname
            versions = glob.glob(os.path.join(staging, "**", f"libmorphreg_{library}.so.*"), recursive=True)
            if not versions:
                sys.exit(f"setup.py: libmorphreg_{library} was not installed under {staging}")
            soname = min(versions, key=len)
            shutil.copy2(os.path.realpath(soname), os.path.join(package, os.path.basename(soname)))


setup(
    version=project_version(),
    packages=["morphreg"],
    package_dir={"morphreg": "python/morphreg"},
    package_data={"morphreg": ["__init__.pyi", "py.typed"]},
    ext_modules=[Extension("morphreg._morphreg", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    options={"build": {"build_base": BUILD_BASE}, "egg_info": {"egg_base": BUILD_BASE}},
    zip_safe=False,
)
