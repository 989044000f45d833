#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Quick start command 1: dependencies, a build of the command line alone (build/tools/morphreg, not the tests),
# then the demo on the built-in synthetic data, into out/demo/.
# The demo's PNG overlay renders through X: without a display it runs under a virtual X server (xvfb-run, installed
# by scripts/install-deps.sh). Extra arguments go to `morphreg demo` (e.g. --count 50, --no-screenshot).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh morphreg_cli
mkdir -p out/demo
if [ -z "${DISPLAY:-}" ] && command -v xvfb-run >/dev/null; then
  exec xvfb-run -a -s "-screen 0 1280x1024x24" ./build/tools/morphreg demo --out-dir out/demo "$@"
fi
exec ./build/tools/morphreg demo --out-dir out/demo "$@"
