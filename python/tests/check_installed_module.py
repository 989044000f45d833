# SPDX-License-Identifier: BSD-3-Clause
"""Imports morphreg from SITE alone and checks it is the installed package: the module file under SITE, its
distribution's version VERSION (importlib.metadata, from the installed dist-info), morphreg's libraries loaded from
LIBDIR, and a computation through them.

usage: check_module.py SITE VERSION LIBDIR
"""
import importlib.metadata
import os
import sys

site, version, libdir = os.path.realpath(sys.argv[1]), sys.argv[2], os.path.realpath(sys.argv[3])
sys.path.insert(0, site)
import morphreg  # noqa: E402


def fail(message):
    print("FAILED: " + message)
    sys.exit(1)


if not os.path.realpath(morphreg.__file__).startswith(site + os.sep):
    fail(f"morphreg imported from {morphreg.__file__}, not from {site}")
if importlib.metadata.version("morphreg") != version or morphreg.__version__ != version:
    fail(f"version {importlib.metadata.version('morphreg')} (metadata), {morphreg.__version__} (module); "
         f"expected {version}")
head = morphreg.HeadGenerator(20).sample(1)
with open("/proc/self/maps") as maps:
    loaded = {line.split()[-1] for line in maps if "libmorphreg_" in line}
if not loaded or not all(os.path.realpath(path).startswith(libdir + os.sep) for path in loaded):
    fail(f"morphreg's libraries loaded from {sorted(loaded)}, expected {libdir}")
print(f"morphreg {version} from {os.path.dirname(morphreg.__file__)}, libraries "
      f"{sorted(os.path.basename(path) for path in loaded)} from {libdir}, a head of {head.vertices.shape[0]} vertices")
