#!/bin/bash
# SPDX-License-Identifier: BSD-3-Clause
# Batch registration end to end: batch.sh <morphreg> <model.h5> <manifest.csv> <work dir> <case>
# Runs are stopped at a known scan by the test-only hook MORPHREG_BATCH_TEST_HOLD=N:DIR (tools/batch_test_hold.h:
# the run writes DIR/held.<share> when it takes its scan N and waits for DIR/release.<share>), never by timing; every
# wait has a time limit.
#   resume-after-kill     killed (SIGKILL) while its second scan is held, then rerun: the stale lock is taken over
#                         and said, the finished scan is not redone, every scan ends complete, no partial file left
#   interrupt             Ctrl-C (SIGINT) while the second scan is held: that scan finishes, exit 130, the other two
#                         are pending in the summary, the lock is released
#   shards-equal-one-run  shards 0/2 and 1/2 merged by merge-summaries give one run's summary (timings aside)
#   merge-other-run       shards made with other settings are not merged: the error names both and the setting
#   other-model           a rerun with another model registers every scan again and says why
#   changed-scan          an id pointed at another scan, and a scan file whose bytes changed, are registered again
#                         (and said); the others are skipped
#   changed-settings      a rerun with another setting registers every scan again, naming the setting; a rerun
#                         with the same settings skips them all
#   live-lock             a second run on a folder in use is refused (exit 1), naming the lock, the owner's pid and
#                         host; a lock of another machine is refused as such; the first run then ends normally
#   stale-lock            a lock left by a process that is gone is taken over with a message
#   shards-and-locks      two shards of one study run side by side on one folder; an unrelated run (another model)
#                         on it is refused while a shard lives
#   cores-from-affinity   the cores counted are those the process may run on (taskset -c 0: one thread a fit)
set -u
morphreg=$1 model=$2 manifest=$3 work=$4 case=$5
rm -rf "$work" && mkdir -p "$work/hold"
children=()
cleanup () { for pid in "${children[@]}"; do kill -9 "$pid" 2> /dev/null; done; }
trap cleanup EXIT
fail () { echo "FAIL: $*"; exit 1; }
reports () { ls "$1" | grep -v '^summary' | grep '\.json$' | sort; }
# The summary without the timing columns (seconds, fit_seconds), which differ between runs.
untimed () { cut -d, -f1-4,7- "$1"; }
scans=$(grep -vc '^scan,' "$manifest")

runs=0
# register --scans over the manifest into $1; further arguments are passed on. Sets $code, and $log, a new file
# with the run's output.
run () {
  local out=$1
  shift
  log=$work/run$((++runs)).log
  "$morphreg" register --scans "$manifest" --model "$model" --out-dir "$out" -q "$@" > "$log" 2>&1
  code=$?
}
# The same in the background, held when it takes its scan $2 (0-based): its pid in $pid, its output in $log.
run_held () {
  local out=$1 index=$2
  shift 2
  log=$work/run$((++runs)).log
  MORPHREG_BATCH_TEST_HOLD=$index:$work/hold "$morphreg" register --scans "$manifest" --model "$model" \
    --out-dir "$out" -q "$@" > "$log" 2>&1 &
  pid=$!
  children+=("$pid")
}
# Waits at most $2 seconds for the file $1.
wait_for () {
  local deadline=$((SECONDS + $2))
  until [ -e "$1" ]; do
    [ $SECONDS -lt $deadline ] || fail "$1 did not appear within $2 s"
    sleep 0.05
  done
}
# Waits at most $2 seconds for the background process $1 to end; its exit code in $code.
wait_exit () {
  local deadline=$((SECONDS + $2))
  while kill -0 "$1" 2> /dev/null; do
    [ $SECONDS -lt $deadline ] || fail "pid $1 still runs after $2 s"
    sleep 0.05
  done
  wait "$1"
  code=$?
}
expect_code () { [ "$code" -eq "$1" ] || { cat "$2"; fail "exit code $code, expected $1 ($2)"; }; }
expect_line () { grep -qF -- "$2" "$1" || { cat "$1"; fail "$1 does not say: $2"; }; }
all_ok () { [ "$(grep -c ',ok,' "$1/summary.csv")" -eq "$scans" ] || fail "not every scan is ok in $1/summary.csv"; }
no_partials () { ! ls -A "$1" | grep -q '^\.partial\.' || fail "partial files are left in $1"; }
# The counts line of a run: "$1 already done (skipped), $2 to register".
expect_counts () { expect_line "$1" "$2 already done (skipped), $3 to register"; }

case $case in
resume-after-kill)
  run_held "$work/out" 1 --jobs 1
  wait_for "$work/hold/held.all" 120
  kill -9 "$pid"
  wait_exit "$pid" 30
  [ "$(reports "$work/out" | wc -l)" -eq 1 ] || fail "not exactly one finished scan before the kill"
  for f in $(reports "$work/out"); do md5sum "$work/out/$f" "$work/out/${f%.json}.ply"; done > "$work/before.md5"
  run "$work/out" --jobs 2
  cat "$log"
  expect_code 0 "$log"
  expect_line "$log" "taking over the stale lock of pid $pid on host $(hostname)"
  expect_counts "$log" 1 $((scans - 1))
  md5sum --quiet -c "$work/before.md5" || fail "a finished scan's outputs were rewritten"
  [ "$(reports "$work/out" | wc -l)" -eq "$scans" ] || fail "not every scan has its report"
  all_ok "$work/out"
  no_partials "$work/out"
  ;;
interrupt)
  run_held "$work/out" 1 --jobs 1
  wait_for "$work/hold/held.all" 120
  kill -INT "$pid"
  wait_exit "$pid" 120
  cat "$log"
  expect_code 130 "$log"
  expect_line "$log" "interrupted; the finished scans' outputs are complete"
  [ "$(grep -c ',ok,' "$work/out/summary.csv")" -eq 2 ] || fail "not exactly 2 scans ok (the held one finishes)"
  [ "$(grep -c ',pending,' "$work/out/summary.csv")" -eq $((scans - 2)) ] || fail "the others are not pending"
  [ "$(reports "$work/out" | wc -l)" -eq 2 ] || fail "the ok scans are not those with a report"
  [ ! -e "$work/out/.morphreg.lock" ] || fail "the lock was not released"
  no_partials "$work/out"
  ;;
shards-equal-one-run)
  run "$work/one"
  expect_code 0 "$log"
  for i in 0 1; do
    run "$work/shards" --shard $i/2
    expect_code 0 "$log"
  done
  "$morphreg" merge-summaries --out-dir "$work/shards" || fail "merge-summaries failed"
  diff <(untimed "$work/one/summary.csv") <(untimed "$work/shards/summary.csv") || fail "the summaries differ"
  diff <(grep '"fingerprint"' "$work/one/summary.json") <(grep '"fingerprint"' "$work/shards/summary.json") ||
    fail "the merged summary names another run than the single run"
  all_ok "$work/one"
  ;;
merge-other-run)
  run "$work/out" --shard 0/2
  expect_code 0 "$log"
  run "$work/out" --shard 1/2 --shape-prior 2
  expect_code 0 "$log"
  "$morphreg" merge-summaries --out-dir "$work/out" > "$work/merge.log" 2>&1
  code=$?
  expect_code 1 "$work/merge.log"
  expect_line "$work/merge.log" "summary.shard-1-of-2.json: made by another run than"
  expect_line "$work/merge.log" "shape_prior_weight 3.0 in $work/out/summary.shard-0-of-2.json, 2.0 in"
  [ ! -e "$work/out/summary.csv" ] || fail "a merged summary was written"
  ;;
other-model)
  data=$(dirname "$manifest")/batch_scans
  "$morphreg" build-model --dir "$data" --regions "$data/regions.json" --landmark-vertices \
    "$data/landmark_vertices.json" --components 2 --quiet --out "$work/other.h5" > /dev/null || fail "build-model"
  run "$work/out"
  expect_code 0 "$log"
  "$morphreg" register --scans "$manifest" --model "$work/other.h5" --out-dir "$work/out" -q > "$work/rerun.log" 2>&1
  code=$?
  cat "$work/rerun.log"
  [ $code -eq 0 ] || [ $code -eq 4 ] || fail "rerun with another model: exit code $code"
  expect_counts "$work/rerun.log" 0 "$scans"
  expect_line "$work/rerun.log" "($scans again: their records do not match this run)"
  [ "$(grep -c "made with another model: \"$work/other.h5\"" "$work/rerun.log")" -eq "$scans" ] ||
    fail "not every scan is said to be registered again for the other model"
  [ "$(grep -l "\"file\": \"$work/other.h5\"" "$work"/out/*.json | grep -vc summary)" -eq "$scans" ] ||
    fail "not every report records the other model"
  ;;
changed-scan)
  data=$(dirname "$manifest")/batch_scans
  cp "$data/scan_0.pcd" "$work/a.pcd" && cp "$data/scan_1.pcd" "$work/b.pcd" && cp "$data/scan_2.pcd" "$work/c.pcd"
  printf 'scan,landmarks,id\na.pcd,,a\nb.pcd,,b\nc.pcd,,c\n' > "$work/study.csv"
  manifest=$work/study.csv scans=3
  run "$work/out"
  expect_code 0 "$log"
  printf 'scan,landmarks,id\na.pcd,,a\nc.pcd,,b\nc.pcd,,c\n' > "$work/study.csv" # b now names scan c
  cp "$data/scan_3.pcd" "$work/a.pcd"                                           # a's bytes change
  run "$work/out"
  cat "$log"
  expect_code 0 "$log"
  expect_counts "$log" 1 2
  expect_line "$log" "registering a again: the scan changed: \"$work/a.pcd\" (fnv1a64"
  expect_line "$log" "registering b again: the scan changed: \"$work/c.pcd\" (fnv1a64"
  grep -q 'registering c again' "$log" && fail "the unchanged scan c was registered again"
  grep -q "\"file\": \"$work/c.pcd\"" "$work/out/b.json" || fail "b's report does not record its new scan"
  ;;
changed-settings)
  run "$work/out"
  expect_code 0 "$log"
  run "$work/out" --shape-prior 2
  cat "$log"
  expect_code 0 "$log"
  expect_counts "$log" 0 "$scans"
  [ "$(grep -c 'made with other settings: shape_prior_weight 2.0 now, 3.0 in the report' "$log")" -eq \
    "$scans" ] || fail "not every scan is said to be registered again for the other shape prior"
  run "$work/out" --shape-prior 2
  expect_code 0 "$log"
  expect_counts "$log" "$scans" 0
  ;;
live-lock)
  run_held "$work/out" 0 --jobs 1
  first=$pid first_log=$log
  wait_for "$work/hold/held.all" 120
  run "$work/out"
  expect_code 1 "$log"
  expect_line "$log" "$work/out/.morphreg.lock: another run is registering the same scans into this folder"
  expect_line "$log" "held by pid $first on host $(hostname)"
  run "$work/out" --shard 0/2
  expect_code 1 "$log"
  expect_line "$log" "$work/out/.morphreg.lock: another run (another study, model, settings or shard count)"
  touch "$work/hold/release.all"
  wait_exit "$first" 300
  expect_code 0 "$first_log"
  all_ok "$work/out"
  [ ! -e "$work/out/.morphreg.lock" ] || fail "the lock was not released"
  mkdir -p "$work/away"
  printf '{"pid": 1, "host": "elsewhere.invalid", "process_start": "1", "started": "then", "run": "x", "shards": 1}' \
    > "$work/away/.morphreg.lock"
  run "$work/away"
  expect_code 1 "$log"
  expect_line "$log" "held by pid 1 on host elsewhere.invalid, since then (another machine"
  ;;
stale-lock)
  true &
  gone=$!
  wait $gone
  mkdir -p "$work/out"
  printf '{"pid": %d, "host": "%s", "process_start": "", "started": "then", "run": "x", "shards": 1}' "$gone" \
    "$(hostname)" > "$work/out/.morphreg.lock"
  run "$work/out"
  cat "$log"
  expect_code 0 "$log"
  expect_line "$log" "$work/out/.morphreg.lock: taking over the stale lock of pid $gone on host"
  all_ok "$work/out"
  [ ! -e "$work/out/.morphreg.lock" ] || fail "the lock was not released"
  ;;
shards-and-locks)
  run_held "$work/out" 0 --shard 0/2 --jobs 1
  first=$pid first_log=$log
  wait_for "$work/hold/held.shard-0-of-2" 120
  run "$work/out" --shard 1/2
  expect_code 0 "$log"
  expect_counts "$log" 0 $((scans / 2))
  run "$work/out" --shard 1/2 --shape-prior 2
  expect_code 1 "$log"
  expect_line "$log" "$work/out/.morphreg.shard-0-of-2.lock: another run (another study, model, settings"
  expect_line "$log" "held by pid $first on host"
  touch "$work/hold/release.shard-0-of-2"
  wait_exit "$first" 300
  expect_code 0 "$first_log"
  "$morphreg" merge-summaries --out-dir "$work/out" || fail "merge-summaries failed"
  all_ok "$work/out"
  ;;
cores-from-affinity)
  command -v taskset > /dev/null || fail "taskset (util-linux) is missing"
  [ "$(nproc --all)" -ge 2 ] || { echo "skipped: one core, nothing to restrict"; exit 77; }
  log=$work/taskset.log
  taskset -c 0 "$morphreg" register --scans "$manifest" --model "$model" --out-dir "$work/out" --jobs 1 --shard 0/4 \
    -q > "$log" 2>&1
  code=$?
  expect_code 0 "$log"
  expect_line "$log" "to register with 1 jobs of 1 threads"
  ;;
*) fail "unknown case $case" ;;
esac
echo "passed: $case"
