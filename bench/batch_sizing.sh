#!/bin/bash
# SPDX-License-Identifier: BSD-3-Clause
# The figures docs/cluster.md's sizing example rests on (issue 37): per-scan time, memory and output size of
# `register --scans` on a real scan, and the time a resumed run spends checking what is done.
#   bench/batch_sizing.sh [SCANS=8] [BUILD_DIR=build] [WORK_DIR=/tmp/morphreg_batch_sizing] [DATA=../shared/data]
# The study: SCANS manifest rows of the real head-and-shoulders scan (real_head_scans/leeperrysmith_scan_82k_mm.ply,
# 82,360 points, 2.0 MB), registered with the ICT-FaceKit model of 30 components per region (11,248 vertices,
# built from ../shared/data/ict_facekit) and the settings of CliTest.RegisterRealScanWithoutLandmarks. Three runs:
#   1 job x 1 thread  (taskset -c 0: one core, as a Slurm task of --cpus-per-task=1 bound to its CPU)
#   1 job x 2 threads (both cores on one scan)
#   2 jobs x 1 thread (both cores, one scan each: the default)
# and a rerun of the last with every scan done (content hashes of each scan and the model checked, then skipped).
# Prints wall time per scan, core-seconds per scan, peak resident memory (/usr/bin/time %M) and the outputs' size.
# No baseline: these are sizes for a plan, not a comparison. Exits 77 (a skip for ctest) without the shared data.
set -euo pipefail
scans=${1:-8}
build=$(realpath "${2:-build}")
work=${3:-/tmp/morphreg_batch_sizing}
data=$(realpath -m "${4:-$(dirname "$0")/../../shared/data}")
morphreg=$build/tools/morphreg
scan=$data/real_head_scans/leeperrysmith_scan_82k_mm.ply
[ -f "$scan" ] || { echo "batch_sizing: $scan is missing (../shared/data absent): skipped"; exit 77; }
rm -rf "$work" && mkdir -p "$work"
cd "$work"
"$morphreg" build-model --from-ict "$data/ict_facekit" --samples 300 --components 30 --quiet --out ict30.h5 > /dev/null
{ echo "scan,landmarks,id"; for ((i = 0; i < scans; ++i)); do echo "$scan,,real_$i"; done; } > manifest.csv
settings=(--components 30 --area-weighting --shape-prior 1.5 --tangential-weight 0.1 --no-target-smoothing --quiet)

# run NAME [COMMAND-PREFIX...]: register --scans with $jobs_args into NAME; prints its figures. CPU time (user + system)
# is counted, not only wall time, as on a machine shared with other work the wall time is not the scans' own.
run () {
  local name=$1
  shift
  /usr/bin/time -f "%e %U %S %M" -o "$name.time" "$@" "$morphreg" register --scans manifest.csv --model ict30.h5 \
    --out-dir "$name" "${settings[@]}" ${jobs_args} > "$name.log" 2>&1 || [ $? -eq 4 ]
  python3 - "$name" "$scans" << 'PY'
import csv, os, sys
name, scans = sys.argv[1], int(sys.argv[2])
wall, user, system, rss = (float(v) for v in open(name + ".time").read().split()[-4:])
rows = list(csv.DictReader(open(name + "/summary.csv")))
ok = sum(r["status"] == "ok" for r in rows)
ply = sum(os.path.getsize(f"{name}/{r['id']}.ply") for r in rows) / len(rows) / 1e6
report = sum(os.path.getsize(f"{name}/{r['id']}.json") for r in rows) / len(rows) / 1e3
print(f"{name}: {scans} scans ({ok} ok): wall {wall:.1f} s ({wall / scans:.2f} s a scan), CPU {user + system:.1f} s "
      f"({(user + system) / scans:.2f} core-s a scan); peak memory {rss / 1024:.0f} MB; "
      f"outputs per scan {ply:.2f} MB mesh + {report:.1f} kB report")
PY
}
jobs_args="--jobs 1" run jobs1_threads1 taskset -c 0
jobs_args="--jobs 1" run jobs1_threads2
jobs_args="--jobs 2" run jobs2_threads1
grep -h 'jobs of' jobs1_threads1.log jobs1_threads2.log jobs2_threads1.log

# Resuming a 200-scan study that is done: the reports of scan 0 copied to 200 ids (their records match: the same
# scan file), so the rerun hashes 200 scans and the model, reads 200 reports and registers none.
mkdir -p resume
{ echo "scan,landmarks,id"; for ((i = 0; i < 200; ++i)); do echo "$scan,,real_$i"; done; } > resume.csv
for ((i = 0; i < 200; ++i)); do
  cp jobs2_threads1/real_0.ply "resume/real_$i.ply" && cp jobs2_threads1/real_0.json "resume/real_$i.json"
done
/usr/bin/time -f "%e %U %S %M" -o resume.time "$morphreg" register --scans resume.csv --model ict30.h5 \
  --out-dir resume "${settings[@]}" > resume.log 2>&1
grep -h 'already done' resume.log
echo "resume of 200 done scans (wall, user, system s, peak kB): $(cat resume.time)"
echo "model file $(stat -c %s ict30.h5) bytes; scan file $(stat -c %s "$scan") bytes"
echo "summary of 200 scans: $(stat -c %s resume/summary.csv) bytes CSV, $(stat -c %s resume/summary.json) bytes JSON;" \
  "the folder of 200 scans' outputs: $(du -sb resume | cut -f1) bytes"
