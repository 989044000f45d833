#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The real-scan zoo: every scan of ../shared/data/real_head_scans registered with `morphreg register`'s defaults only
# (the ICT-FaceKit model built as the README builds it; --landmarks where a case has them), from its own pose, from
# random poses (any rotation, scale 0.85-1.15, in mm and in m) and as simulated depth-camera frames (Kinect v1 class,
# frontal, 45 degrees and profile, 1 m away; the head crop and the whole scene with a wall and a floor). Each fit is
# scored by the convention of real_head_scans/README.md (area samples of the true surface to the fitted surface, the
# face's median) and one table is printed; --check asserts the targets (issue 31) and exits 1 if one is missed.
#
#   scripts/real_scan_zoo.sh [--poses N] [--check] [--build DIR] [--out DIR] [--jobs N] [--data DIR]
#     --poses N   random poses per scan and unit (default 8; the ctest runs 1)
#     --check     exit 1 unless every case exits 0 with status ok within its face-median target
#     --known-miss NAME  a case known to miss its target (repeatable): reported, not failed; --check fails if it
#                 meets its target (so that the list only shrinks)
#     --build     the build folder with tools/morphreg and test/morphreg_zoo_tool (default build)
#     --out       the work folder (default out/zoo)
#     --jobs      registrations at once (default 2, each on one core)
#     --data      the shared data sets (default ../shared/data)
set -uo pipefail
cd "$(dirname "$0")/.."
POSES=8 CHECK=0 BUILD=build OUT=out/zoo JOBS=2 DATA=../shared/data KNOWN_MISSES=
while [ $# -gt 0 ]; do
  case $1 in
    --poses) POSES=$2; shift 2 ;;
    --check) CHECK=1; shift ;;
    --known-miss) KNOWN_MISSES="$KNOWN_MISSES $2"; shift 2 ;;
    --build) BUILD=$2; shift 2 ;;
    --out) OUT=$2; shift 2 ;;
    --jobs) JOBS=$2; shift 2 ;;
    --data) DATA=$2; shift 2 ;;
    *) echo "real_scan_zoo: unknown argument $1" >&2; exit 2 ;;
  esac
done
SCANS=$DATA/real_head_scans
if [ ! -d "$SCANS" ] || [ ! -f "$DATA/ict_facekit/ict_head_pca_basis.npy" ]; then
  echo "SKIPPED: $SCANS or ICT-FaceKit is absent (the shared real data sets, ../shared/data)"
  exit 0
fi
MORPHREG=$BUILD/tools/morphreg TOOL=$BUILD/test/morphreg_zoo_tool
for program in "$MORPHREG" "$TOOL"; do
  [ -x "$program" ] || { echo "real_scan_zoo: $program is not built" >&2; exit 2; }
done
mkdir -p "$OUT"
MODEL=$OUT/ict30.h5
[ -f "$MODEL" ] || "$MORPHREG" build-model --from-ict "$DATA/ict_facekit" --samples 300 --components 30 --quiet \
  --out "$MODEL" || exit 1

LPS_MESH=$SCANS/leeperrysmith_head_mm.ply
# name | scan | true surface | face-median target (mm) | landmarks
CASES=(
  "lps_cloud|$SCANS/leeperrysmith_scan_82k_mm.ply|$LPS_MESH|0.75|"
  "lps_mesh|$LPS_MESH|$LPS_MESH|0.9|"
  "james|$SCANS/menpo3d_james/james.obj|$SCANS/menpo3d_james/james.obj|1.0|"
  "james_landmarks|$SCANS/menpo3d_james/james.obj|$SCANS/menpo3d_james/james.obj|1.0|$SCANS/menpo3d_james/james_landmarks.json"
  "demoface|$SCANS/meshmonk_demoface/demoface_10k.obj|$SCANS/meshmonk_demoface/demoface_10k.obj|0.8|"
)
JOBS_FILE=$OUT/jobs.txt
: > "$JOBS_FILE"
add_job () { echo "$*" >> "$JOBS_FILE"; } # name | scan | truth | target | landmarks | pose file
for entry in "${CASES[@]}"; do
  IFS='|' read -r name scan truth target landmarks <<< "$entry"
  add_job "$name|$scan|$truth|$target|$landmarks|"
  [ -n "$landmarks" ] && continue # landmarks are in the scan's own frame
  for ((seed = 1; seed <= POSES; seed++)); do
    for unit in mm m; do
      posed=$OUT/${name}_pose${seed}_$unit.ply
      "$TOOL" pose "$scan" "$posed" $((100 + seed)) $unit || exit 1
      add_job "${name}_pose${seed}_$unit|$posed|$truth|$target||$posed.pose.json"
    done
  done
done
for mesh in lps_mesh:$LPS_MESH james:$SCANS/menpo3d_james/james.obj demoface:$SCANS/meshmonk_demoface/demoface_10k.obj; do
  name=${mesh%%:*} file=${mesh#*:}
  for view in frontal oblique profile; do
    for kind in crop scene; do
      frame=$OUT/${name}_depth_${view}_$kind.pcd
      "$TOOL" depth "$file" "$frame" $view 1000 7 $([ $kind = scene ] && echo scene) || exit 1
      # The crops as organised PCDs in metres (PCL's grabbers), the scenes as depth images in mm (--depth)
      scan=$frame
      [ $kind = scene ] && scan=depth:${frame%.pcd}.png
      add_job "${name}_depth_${view}_$kind|$scan|$file|2.0||$frame.pose.json"
    done
  done
done

# One registration and its score: a table row on stdout.
run_case () {
  IFS='|' read -r name scan truth target landmarks pose <<< "$1"
  local fit=$OUT/$name.fit.ply report=$OUT/$name.fit.json log=$OUT/$name.log start end code status score median
  start=$(date +%s.%N)
  local input=(--scan "$scan") image=${scan#depth:}
  [[ $scan == depth:* ]] && input=(--depth "$image" --intrinsics "${image%.png}.intrinsics.json")
  OMP_NUM_THREADS=1 "$MORPHREG" register "${input[@]}" --model "$MODEL" ${landmarks:+--landmarks "$landmarks"} \
    --out "$fit" --quiet > "$log" 2>&1
  code=$?
  end=$(date +%s.%N)
  status=$(python3 -c "import json,sys; print(json.load(open(sys.argv[1])).get('status','-'))" "$report" 2>/dev/null || echo -)
  median=-
  if [ -f "$fit" ]; then
    score=$("$TOOL" score "$fit" "$truth" $pose 2>> "$log")
    median=$(python3 -c "import json,sys; print('%.3f' % json.loads(sys.argv[1])['face_median'])" "$score" 2>/dev/null || echo -)
  fi
  printf '%s|%s|%s|%s|%s|%.1f\n' "$name" "$code" "$status" "$median" "$target" "$(echo "$end - $start" | bc)"
}
export -f run_case
export OUT MODEL MORPHREG TOOL
ROWS=$OUT/rows.txt
xargs -a "$JOBS_FILE" -d '\n' -P "$JOBS" -I{} bash -c 'run_case "$1"' _ {} > "$ROWS"

sort "$ROWS" | python3 -c '
import sys
known = set(sys.argv[1].split())
rows = [line.rstrip("\n").split("|") for line in sys.stdin]
missed = failures = 0
print("%-34s %4s %-7s %12s %7s %7s  %s" % ("case", "rc", "status", "face median", "target", "seconds", "verdict"))
for name, code, status, median, target, seconds in rows:
    ok = code == "0" and status == "ok" and median != "-" and float(median) <= float(target)
    missed += not ok
    verdict = "ok" if ok else "MISSED"
    if name in known:
        verdict = "ok, but listed as a known miss: take it off the list" if ok else "MISSED (a known miss)"
        failures += ok
    else:
        failures += not ok
    print("%-34s %4s %-7s %12s %7s %7s  %s" % (name, code, status, median, target, seconds, verdict))
print("%d of %d cases within their targets" % (len(rows) - missed, len(rows)))
sys.exit(1 if failures else 0)
' "$KNOWN_MISSES"
verdict=$?
[ $CHECK -eq 1 ] && exit $verdict
exit 0
