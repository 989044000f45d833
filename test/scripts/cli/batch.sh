#!/bin/bash
# SPDX-License-Identifier: BSD-3-Clause
# Batch registration end to end: batch.sh <morphreg> <model.h5> <manifest.csv> <work dir> <case>
#   resume-after-kill     a run killed (SIGKILL) after its first finished scan, then rerun: no finished scan is
#                         redone or lost, every scan ends complete, no partial file is left
#   interrupt             Ctrl-C (SIGINT) after the first finished scan: the scan in progress finishes, exit 130,
#                         the summary lists the others as pending, no partial file is left
#   shards-equal-one-run  shards 0/2 and 1/2 merged by merge-summaries give one run's summary (timings aside)
set -u
morphreg=$1 model=$2 manifest=$3 work=$4 case=$5
rm -rf "$work" && mkdir -p "$work"
fail () { echo "FAIL: $*"; exit 1; }
reports () { ls "$1" | grep -v '^summary' | grep '\.json$' | sort; }
# The summary without the timing columns (seconds, fit_seconds), which differ between runs.
untimed () { cut -d, -f1-4,7- "$1"; }
scans=$(grep -vc '^scan,' "$manifest")

case $case in
resume-after-kill)
  "$morphreg" register --scans "$manifest" --model "$model" --out-dir "$work/out" --jobs 1 -q > "$work/first.log" 2>&1 &
  pid=$!
  for _ in $(seq 600); do [ -n "$(reports "$work/out" 2>/dev/null)" ] && break; sleep 0.05; done
  kill -9 $pid; wait $pid 2>/dev/null
  finished=$(reports "$work/out")
  [ -n "$finished" ] || fail "no scan finished before the kill"
  [ "$(echo "$finished" | wc -l)" -lt "$scans" ] || fail "every scan finished before the kill; nothing to resume"
  for f in $finished; do md5sum "$work/out/$f" "$work/out/${f%.json}.ply"; done > "$work/before.md5" 2>/dev/null
  "$morphreg" register --scans "$manifest" --model "$model" --out-dir "$work/out" --jobs 2 -q > "$work/second.log" 2>&1
  cat "$work/second.log"
  skipped=$(echo "$finished" | wc -l)
  grep -q "$skipped already done (skipped), $((scans - skipped)) to register" "$work/second.log" ||
    fail "the rerun did not skip exactly the $skipped finished scans"
  md5sum --quiet -c "$work/before.md5" || fail "a finished scan's outputs were rewritten"
  [ "$(reports "$work/out" | wc -l)" -eq "$scans" ] || fail "not every scan has its report"
  [ "$(grep -c ',ok,' "$work/out/summary.csv")" -eq "$scans" ] || fail "not every scan is ok in the summary"
  ! ls -A "$work/out" | grep -q '^\.partial\.' || fail "partial files are left"
  ;;
interrupt)
  "$morphreg" register --scans "$manifest" --model "$model" --out-dir "$work/out" --jobs 1 -q > "$work/first.log" 2>&1 &
  pid=$!
  for _ in $(seq 600); do [ -n "$(reports "$work/out" 2>/dev/null)" ] && break; sleep 0.05; done
  kill -INT $pid
  wait $pid
  code=$?
  cat "$work/first.log"
  [ $code -eq 130 ] || fail "Ctrl-C: exit code $code, expected 130"
  grep -q "interrupted; the finished scans' outputs are complete" "$work/first.log" || fail "no interruption message"
  grep -q ',pending,' "$work/out/summary.csv" || fail "the summary lists no pending scan"
  [ "$(grep -c ',ok,' "$work/out/summary.csv")" -eq "$(reports "$work/out" | wc -l)" ] ||
    fail "the summary's ok scans are not those with a report"
  ! ls -A "$work/out" | grep -q '^\.partial\.' || fail "partial files are left"
  ;;
shards-equal-one-run)
  "$morphreg" register --scans "$manifest" --model "$model" --out-dir "$work/one" -q || fail "one run failed"
  for i in 0 1; do
    "$morphreg" register --scans "$manifest" --model "$model" --out-dir "$work/shards" --shard $i/2 -q ||
      fail "shard $i/2 failed"
  done
  "$morphreg" merge-summaries --out-dir "$work/shards" || fail "merge-summaries failed"
  diff <(untimed "$work/one/summary.csv") <(untimed "$work/shards/summary.csv") || fail "the summaries differ"
  [ "$(grep -c ',ok,' "$work/one/summary.csv")" -eq "$scans" ] || fail "not every scan is ok"
  ;;
*) fail "unknown case $case" ;;
esac
echo "passed: $case"
