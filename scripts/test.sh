#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Quick start command 2: dependencies, configure, build, then every test through ctest.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
cd build
ctest --output-on-failure -j2 --timeout 900
