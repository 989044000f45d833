#!/usr/bin/env bash
# Quick start command 1: dependencies, build, then the demo on the built-in synthetic data.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
mkdir -p out/demo
./build/tools/morphreg demo --out out/demo "$@"
