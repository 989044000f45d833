#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Slow checks that run outside CI (docs/FUZZING.md says when):
#   scripts/check.sh sanitize                        GCC build with -fsanitize=address,undefined into build-asan/,
#                                                    then the whole test suite under the sanitizers
#   scripts/check.sh fuzz [seconds] [target...]      clang/libFuzzer build into build-fuzz/, then each target (all by
#                                                    default) for <seconds> (default 60) over fuzz/corpus/<target>/
# Both run niced with at most two jobs, as the machine is shared.
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$(pwd)

# Sanitizer settings shared by both: stop at the first report, and keep the leak suppressions of system libraries.
# alloc_dealloc_mismatch=0: PCL's own compiled code frees with delete memory it allocated with malloc (vtk2mesh on
# every VTK and STL file, CorrespondenceRejectorMedianDistance::setSourcePoints, PCLVisualizer::addPolygonMesh),
# harmless with glibc and not in morphreg's code.
export ASAN_OPTIONS="halt_on_error=1:detect_leaks=1:strict_string_checks=1:alloc_dealloc_mismatch=0"
export LSAN_OPTIONS="suppressions=$ROOT/scripts/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"

FUZZ_TARGETS=(model_h5 mesh_ply mesh_obj mesh_pcd mesh_vtk mesh_stl mesh_off landmarks_pp landmarks_json
              landmarks_csv landmarks_pts photo_json npy skeleton_json photo_png photo_jpeg model_contents mesh_glb mesh_gltf)

install_missing() {
  local missing=()
  for pkg in "$@"; do
    dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed" || missing+=("$pkg")
  done
  if [ ${#missing[@]} -gt 0 ]; then
    echo "check: installing ${missing[*]}"
    local sudo=""
    [ "$(id -u)" -eq 0 ] || sudo="sudo"
    DEBIAN_FRONTEND=noninteractive $sudo apt-get update
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y --no-install-recommends "${missing[@]}"
  fi
}

sanitize() {
  bash scripts/install-deps.sh
  # The Python module is left out: an instrumented extension cannot load into Debian's uninstrumented interpreter
  # without preloading the sanitizer runtime; the library code it wraps is what the suite checks.
  cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DMORPHREG_SANITIZE=address,undefined \
    -DMORPHREG_BUILD_BENCHMARKS=OFF -DMORPHREG_BUILD_PYTHON=OFF -DMORPHREG_TEST_TIMEOUT_FACTOR=10
  nice -n 10 cmake --build build-asan -j2
  # PackageTest builds consumer projects without the sanitizers against the installed (instrumented) libraries,
  # which cannot load without the sanitizer runtime first: it checks the packaging, which the normal suite does.
  cd build-asan
  # Under the sanitizers a fit runs 10 to 30 times slower: the accuracy suites run 2 of their heads or poses each
  # (test/support/sample_count.h), every code path they take but not the hours their 20 heads would cost.
  MORPHREG_TEST_SAMPLES=2 nice -n 10 ctest --output-on-failure -j2 --timeout 3600 -E '^PackageTest\.'
}

# Runs one fuzz target for $1 seconds over its committed corpus and its scratch corpus (build-fuzz/corpus/<target>/,
# kept between runs), where new inputs go. -fork=1 runs one worker process, restarted after a finding: crashes,
# leaks, timeouts and out-of-memory inputs are written to fuzz/crashes/<target>/ and the run goes on. Then the
# scratch inputs that reach code the committed corpus does not are merged into it; counting edges only
# (-use_counters=0) keeps the committed corpus small. Fails if the run found anything new.
fuzz_target() {
  local seconds=$1 target=$2
  local binary="build-fuzz/fuzz/fuzz_$target" corpus="fuzz/corpus/$target" scratch="build-fuzz/corpus/$target"
  local log="build-fuzz/logs/$target.log" crashes="fuzz/crashes/$target"
  mkdir -p "$scratch" "$crashes" "$(dirname "$log")"
  local before status=0
  before=$(find "$crashes" -type f | wc -l)
  /usr/bin/time -f 'cpu %U s user + %S s system' -o "$log.time" \
    nice -n 10 "$binary" "$scratch" "$corpus" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
    -fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1 -artifact_prefix="$crashes/" >"$log" 2>&1 ||
    status=$?
  nice -n 10 "$binary" -merge=1 -use_counters=0 "$corpus" "$scratch" >"$log.merge" 2>&1
  local found
  found=$(( $(find "$crashes" -type f | wc -l) - before ))
  rmdir --ignore-fail-on-non-empty "$crashes"
  printf '%-15s status %d  %s  execs %s  %s  corpus %d files %d bytes  new findings %d\n' "$target" "$status" \
    "$(grep -oE 'cov: [0-9]+ ft: [0-9]+' "$log" | tail -1 || echo 'cov: ? ft: ?')" \
    "$(grep -oE '^#[0-9]+' "$log" | tail -1 | tr -d '#')" "$(tail -1 "$log.time")" \
    "$(find "$corpus" -type f | wc -l)" "$(cat "$corpus"/* | wc -c)" "$found"
  [ "$status" -eq 0 ] && [ "$found" -eq 0 ]
}

fuzz() {
  local seconds=${1:-60}
  shift || true
  local targets=("$@")
  [ ${#targets[@]} -gt 0 ] || targets=("${FUZZ_TARGETS[@]}")
  install_missing clang-14 libclang-rt-14-dev libomp-14-dev llvm-14
  CC=clang-14 CXX=clang++-14 cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DMORPHREG_BUILD_FUZZERS=ON \
    -DMORPHREG_BUILD_TESTS=OFF -DMORPHREG_BUILD_TOOLS=OFF -DMORPHREG_BUILD_SAMPLES=OFF \
    -DMORPHREG_BUILD_BENCHMARKS=OFF -DMORPHREG_BUILD_PYTHON=OFF -DMORPHREG_TEST_TIMEOUT_FACTOR=10 -DMORPHREG_PRECOMPILED_HEADERS=OFF >/dev/null
  nice -n 10 cmake --build build-fuzz -j2 --target "${targets[@]/#/fuzz_}"
  export ASAN_SYMBOLIZER_PATH=/usr/bin/llvm-symbolizer-14
  # The inputs are written to a file per run; a RAM disk keeps that cheap.
  [ -d /dev/shm ] && export TMPDIR=/dev/shm
  local failed=0
  for target in "${targets[@]}"; do
    fuzz_target "$seconds" "$target" || failed=1
  done
  [ $failed -eq 0 ] || echo "check: findings above; reproducers are in fuzz/crashes/, logs in build-fuzz/logs/" >&2
  return $failed
}

case "${1:-}" in
  sanitize) sanitize ;;
  fuzz) shift; fuzz "$@" ;;
  *) echo "usage: scripts/check.sh sanitize | fuzz [seconds-per-target] [target...]" >&2; exit 2 ;;
esac
