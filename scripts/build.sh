#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Installs dependencies, configures and builds morphreg (Release) into build/: every target, or only the targets
# given as arguments (scripts/demo.sh builds just the command line, morphreg_cli).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
if [ $# -eq 0 ]; then
  cmake --build build -j2
else
  cmake --build build -j2 --target "$@"
fi
