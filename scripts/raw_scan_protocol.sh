#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The raw-scan model protocol of docs/accuracy.md ("A model from raw scans"), by the command line: a model of 200
# synthetic heads (seeds 1-200) registers simulated laser scans of 100 unseen heads (seeds 1001-1100; point clouds,
# sigma 0.2 mm, the scanner's holes and random pose, true size), `build-model --from-scans` builds a model from them,
# and `evaluate-model` compares it with the model of the same heads' true meshes on 20 further heads (1101-1120).
# Usage: scripts/raw_scan_protocol.sh [OUTPUT_DIR]   (default out/raw_scan_protocol; MORPHREG = the CLI binary)
set -euo pipefail
cli=${MORPHREG:-build/tools/morphreg}
out=${1:-out/raw_scan_protocol}
mkdir -p "$out"

"$cli" synth --seed 1 --count 200 --out-dir "$out/population" --quiet
"$cli" build-model --dir "$out/population" --regions "$out/population/regions.json" \
    --landmark-vertices "$out/population/landmark_vertices.json" --components 60 --out "$out/registering.h5" --quiet
"$cli" synth --seed 1001 --count 100 --scans 100 --scale-deviation 0 --out-dir "$out/scanned" --quiet
for i in $(seq 0 99); do echo "scan_$i.pcd"; done >"$out/scanned/manifest.csv"
"$cli" build-model --from-scans "$out/scanned/manifest.csv" --model "$out/registering.h5" --components 20 \
    --report-dir "$out/raw_scans" --out "$out/raw.h5"
"$cli" build-model --dir "$out/scanned" --components 20 --out "$out/true.h5" --quiet
"$cli" synth --seed 1101 --count 20 --out-dir "$out/held_out" --quiet

# The resampled meshes of the scans that made it (a scan left out has its report but no <id>.ply).
mapfile -t resampled < <(find "$out/raw_scans" -name 'scan_*.ply' ! -name '*_fit.ply' | sort)
mapfile -t heads < <(find "$out/scanned" -name 'head_*.ply' | sort)
for model in raw true; do
  if [ "$model" = raw ]; then training=("${resampled[@]}"); else training=("${heads[@]}"); fi
  "$cli" evaluate-model --model "$out/$model.h5" --meshes "$out/held_out" --training "${training[@]}" \
      --components 5,10,20 --json --quiet >"$out/quality_$model.json"
  echo "wrote $out/quality_$model.json"
done
