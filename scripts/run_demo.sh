#!/usr/bin/env bash
# The main job on an embedded default: installs what is missing, builds, renders a generated
# corridor sequence, recovers its depth, evaluates it against the ground truth, and says where
# everything is. Usage (as root on a fresh machine): bash scripts/run_demo.sh [OUT_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
OUT=${1:-out/demo}
bash scripts/install_deps.sh
bash scripts/build.sh
BIN=${BUILD_DIR:-build}/tools
rm -rf "$OUT"
"$BIN/corridor_synth" --preset=sequence --frames=12 --seed=7 --output_dir="$OUT/dataset"
status=0
"$BIN/corridor_depth" --input="$OUT/dataset" --output_dir="$OUT/depth" || status=$?
"$BIN/corridor_eval" --dataset="$OUT/dataset" --output_dir="$OUT/eval" || status=$?
cat <<MSG

Demo outputs:
  generated corridor (rgb, 16-bit depth, camera.yaml, truth.yaml): $OUT/dataset
  recovered depth (16-bit mm PNG) and geometry.csv:                 $OUT/depth/<scene>/
  pictures (input + junction lines | depth):                        $OUT/depth/<scene>/vis/
  metrics against ground truth (report.md, report.json, index.html): $OUT/eval/
MSG
[ -f "$OUT/eval/report.md" ] && sed -n '1,40p' "$OUT/eval/report.md"
exit $status
