#!/bin/bash
# SPDX-License-Identifier: BSD-3-Clause
# register --scans as a Slurm job array, on a one-node Slurm started for the test (scripts/local_slurm.sh):
#   slurm_array.sh <morphreg> <model.h5> <batch scans folder> <work dir> <project folder>
# Submits docs/register_study.sbatch itself (the script docs/cluster.md shows) as an array of 3 tasks over a
# 6-scan study, with task 1 held at its second scan (the test-only hook MORPHREG_BATCH_TEST_HOLD, see
# tools/batch_test_hold.h) and cancelled there with scancel; resubmits that task alone the way docs/cluster.md
# says, merges the shard summaries and checks that they equal one single-machine run of the study (ids, statuses,
# RMS and iterations as printed), that the cancelled task's finished scan was not redone, and that none is missing.
# Exit 77 (skipped) with the reason when Slurm cannot run here (not installed, not root). Every wait has a limit;
# the daemons are stopped on every exit.
set -u
morphreg=$1 model=$2 data=$3 work=$4 project=$5
script=$project/docs/register_study.sbatch
fail () { echo "FAIL: $*"; exit 1; }
rm -rf "$work" && mkdir -p "$work/study/fits" "$work/hold" "$work/logs" "$work/bin" || fail "cannot create $work"
work=$(realpath "$work")

cluster=""
stop_cluster () {
  [ -n "$cluster" ] || return 0
  bash "$project/scripts/local_slurm.sh" stop "$cluster" > /dev/null 2>&1
  if [ "${passed:-0}" = 1 ]; then rm -rf "$cluster"; else echo "the cluster's logs are in $cluster/log"; fi
}
trap stop_cluster EXIT
trap 'exit 1' INT TERM
started=$SECONDS
cluster=$(LOCAL_SLURM_WATCH_PID=$$ bash "$project/scripts/local_slurm.sh" start)
status=$?
[ $status -eq 77 ] && { echo "skipped: Slurm cannot run here (see the line above)"; exit 77; }
[ $status -eq 0 ] || fail "scripts/local_slurm.sh start failed"
# shellcheck disable=SC1091
source "$cluster/env.sh"
echo "a one-node Slurm in $cluster, up in $((SECONDS - started)) s"

# The study: the 4 batch scans, two of them twice under other ids, so that each of 3 shards has 2 scans.
{
  echo "scan,landmarks,id"
  echo "$data/scan_0.pcd,$data/scan_0_landmarks.json,s0"
  for i in 1 2 3; do echo "$data/scan_$i.pcd,,s$i"; done
  echo "$data/scan_0.pcd,,s4"
  echo "$data/scan_1.pcd,,s5"
} > "$work/study/manifest.csv"
ln -s "$(realpath "$model")" "$work/study/model.h5"
ln -s "$(realpath "$morphreg")" "$work/bin/morphreg"
export PATH=$work/bin:$PATH STUDY=$work/study
cd "$work" || fail "cd $work"

# Waits at most $1 seconds until the command $2... succeeds.
wait_until () {
  local limit=$1 deadline=$((SECONDS + $1))
  shift
  until "$@"; do
    [ $SECONDS -lt $deadline ] || fail "waited $limit s for: $*"
    sleep 0.2
  done
}
state () { scontrol show job "$1" 2> /dev/null | grep -o 'JobState=[A-Z_]*' | head -1 | cut -d= -f2; }
has_state () { [ "$(state "$1")" = "$2" ]; }
array_gone () { [ -z "$(squeue -h -j "$1" -o %i 2> /dev/null)" ]; }
untimed () { cut -d, -f1-4,7- "$1"; }

# The same study on one machine, one scan at a time, as each array task runs it (--jobs = its one CPU).
morphreg register --scans "$STUDY/manifest.csv" --model "$STUDY/model.h5" --out-dir "$work/single" --jobs 1 \
  --quiet > "$work/single.log" 2>&1 || { cat "$work/single.log"; fail "the single-machine run failed"; }

# The array: task 1 holds when it takes its second scan; tasks 0 and 2 find their release files and go on.
touch "$work/hold/release.shard-0-of-3" "$work/hold/release.shard-2-of-3"
job=$(MORPHREG_BATCH_TEST_HOLD=1:$work/hold sbatch --parsable --array=0-2 --cpus-per-task=1 --mem=200M "$script") ||
  fail "sbatch $script failed"
echo "submitted $script as job array $job (3 tasks)"
wait_until 120 test -e "$work/hold/held.shard-1-of-3"
held_pid=$(cat "$work/hold/held.shard-1-of-3")
kill -0 "$held_pid" 2> /dev/null || fail "the held task's morphreg (pid $held_pid) does not run"
finished=$(grep -l '"status"' "$STUDY/fits/s1.json" "$STUDY/fits/s4.json" 2> /dev/null)
[ "$finished" = "$STUDY/fits/s1.json" ] || fail "task 1 should have finished s1 and not s4 when held: '$finished'"
md5sum "$STUDY/fits/s1.json" "$STUDY/fits/s1.ply" > "$work/s1.md5"

scancel "${job}_1" || fail "scancel ${job}_1 failed"
wait_until 60 has_state "${job}_1" CANCELLED
wait_until 30 bash -c "! kill -0 $held_pid 2> /dev/null"
wait_until 240 array_gone "$job"
for task in 0 2; do
  has_state "${job}_$task" COMPLETED || fail "task $task: $(state "${job}_$task"), expected COMPLETED"
done
[ ! -e "$STUDY/fits/summary.shard-1-of-3.json" ] || fail "the cancelled task wrote its summary"
[ ! -e "$STUDY/fits/.morphreg.shard-1-of-3.lock" ] || fail "the cancelled task left its lock"
morphreg merge-summaries --out-dir "$STUDY/fits" > "$work/merge_early.log" 2>&1 &&
  fail "merge-summaries merged without the cancelled shard"
grep -q "shard 1/3 is missing" "$work/merge_early.log" || fail "merge-summaries did not name the missing shard"

# Task 1 again, alone, as docs/cluster.md says (with RETRY=--retry-failed, which no scan needs here, to see it
# reach morphreg); without the hold.
again=$(env -u MORPHREG_BATCH_TEST_HOLD sbatch --parsable --array=1 --export=ALL,SHARD=1/3,RETRY=--retry-failed \
  --cpus-per-task=1 --mem=200M "$script") || fail "resubmitting task 1 failed"
wait_until 240 array_gone "$again"
has_state "${again}_1" COMPLETED || fail "the resubmitted task: $(state "${again}_1"), expected COMPLETED"
log=$(ls "$work"/logs/*_"${again}"_1.out) || fail "no log of the resubmitted task"
cat "$log"
grep -q "2 scans in shard 1/3, 1 already done (skipped), 1 to register" "$log" ||
  fail "the resubmitted task did not skip exactly the scan finished before the cancel"
md5sum --quiet -c "$work/s1.md5" || fail "the scan finished before the cancel was registered again"

morphreg merge-summaries --out-dir "$STUDY/fits" || fail "merge-summaries failed"
diff <(untimed "$work/single/summary.csv") <(untimed "$STUDY/fits/summary.csv") ||
  fail "the merged summary differs from the single-machine run's"
[ "$(grep -c ',ok,' "$STUDY/fits/summary.csv")" -eq 6 ] || fail "not all 6 scans are ok"
[ "$(ls "$STUDY"/fits/s?.json | wc -l)" -eq 6 ] || fail "not exactly the 6 scans' reports"
! ls -A "$STUDY/fits" | grep -q '^\.partial\.\|\.lock$' || fail "partial files or locks are left"
passed=1
echo "passed: slurm job array in $((SECONDS - started)) s"
