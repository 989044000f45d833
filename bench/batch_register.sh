#!/bin/bash
# SPDX-License-Identifier: BSD-3-Clause
# Batch registration against a shell loop of single `register` calls, in the same run (issue 17):
#   bench/batch_register.sh [SCANS=200] [BUILD_DIR=build] [WORK_DIR=/tmp/morphreg_batch_bench]
# Makes SCANS synthetic scans (one per head, 3458-vertex heads) and a model of those heads, then times
#   loop:          for each scan `morphreg register --scan` (each call loads the model; OpenMP default: every core)
#   batch, jobs 1: `register --scans --jobs 1` (one scan at a time with every core: the loop's thread settings)
#   batch:         `register --scans` (default --jobs = cores, each fit cores/jobs threads)
# and prints scans per minute, the ratios, the peak resident memory (/usr/bin/time %M) and the share of each scan's
# time spent outside the fit (from summary.csv: seconds - fit_seconds, over seconds; and over the whole run: 1 - the
# fits' seconds / (wall seconds x jobs), which counts the model load and the batch's own work). No external baseline:
# PCL and VTK have no batch registration, so the batch is compared with morphreg's own single-scan command. Results:
# bench/RESULTS.md.
set -euo pipefail
scans=${1:-200}
build=$(realpath "${2:-build}")
work=${3:-/tmp/morphreg_batch_bench}
morphreg=$build/tools/morphreg
rm -rf "$work" && mkdir -p "$work/loop"
cd "$work"

"$morphreg" synth --count "$scans" --resolution 24 --scans "$scans" --angular-samples 200 --row-spacing 3 --quiet \
  --out-dir data > /dev/null
"$morphreg" build-model --dir data --regions data/regions.json --landmark-vertices data/landmark_vertices.json \
  --components 8 --quiet --out model.h5 > /dev/null
{ echo "scan,landmarks,id"; for ((i = 0; i < scans; ++i)); do echo "data/scan_$i.pcd,,scan_$i"; done; } > manifest.csv

now () { date +%s.%N; }
start=$(now)
for ((i = 0; i < scans; ++i)); do
  /usr/bin/time -f %M -a -o loop_rss.txt "$morphreg" register --scan "data/scan_$i.pcd" --model model.h5 \
    --out "loop/scan_$i.ply" --quiet > /dev/null 2>&1 || [ $? -eq 4 ]
done
loop_seconds=$(echo "$(now) - $start" | bc)

run_batch () { # name, extra arguments
  local name=$1
  shift
  start=$(now)
  /usr/bin/time -f %M -o "$name.rss" "$morphreg" register --scans manifest.csv --model model.h5 --out-dir "$name" \
    --quiet "$@" > "$name.log" 2>&1 || [ $? -eq 4 ]
  echo "$(now) - $start" | bc > "$name.seconds"
}
run_batch batch_jobs1 --jobs 1
run_batch batch

python3 - "$scans" "$loop_seconds" "$(nproc)" <<'PY'
import csv, sys
scans, loop_seconds, cores = int(sys.argv[1]), float(sys.argv[2]), int(sys.argv[3])
loop_rss = max(int(line) for line in open("loop_rss.txt") if line.strip().isdigit())
def batch(name):
    rows = list(csv.DictReader(open(name + "/summary.csv")))
    seconds = float(open(name + ".seconds").read())
    total = sum(float(r["seconds"]) for r in rows if r["seconds"])
    fit = sum(float(r["fit_seconds"]) for r in rows if r["fit_seconds"])
    ok = sum(r["status"] == "ok" for r in rows)
    rss = int(open(name + ".rss").read().split()[-1])
    jobs = int(open(name + ".log").read().split(" jobs of ")[0].split()[-1])
    return seconds, ok, (total - fit) / total, rss, 1 - fit / (seconds * jobs), jobs
loop_ok = sum(1 for i in range(scans) if '"status": "ok"' in open("loop/scan_%d.json" % i).read())
loop_rate = scans / loop_seconds * 60
print("%d scans, %d cores (no external baseline: the batch against morphreg's own loop)" % (scans, cores))
print("loop of single register calls: %.1f s, %.1f scans/min, %d ok, peak memory %.0f MB per call"
      % (loop_seconds, loop_rate, loop_ok, loop_rss / 1024))
for name, label in (("batch_jobs1", "register --scans --jobs 1"), ("batch", "register --scans (jobs = cores)")):
    seconds, ok, outside, rss, outside_run, jobs = batch(name)
    rate = scans / seconds * 60
    print("%s: %.1f s, %.1f scans/min = %.2fx the loop, %d ok, peak memory %.0f MB, time outside the fit %.1f %% "
          "per scan, %.1f %% of wall time x %d jobs"
          % (label, seconds, rate, rate / loop_rate, ok, rss / 1024, 100 * outside, 100 * outside_run, jobs))
PY
