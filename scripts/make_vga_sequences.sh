#!/usr/bin/env bash
# Renders the "VGA sequences" evaluation set of docs/results.md: 8 scenes x 12 frames at 640x480,
# corridor widths 1.6-3.2 m, ceilings 2.4-3.3 m, 60-90 degrees across, boxes, doors and floor/wall
# contrasts varied, camera yaw, offset and pitch varied per scene.
# Usage: bash scripts/make_vga_sequences.sh OUTPUT_DIR   (after scripts/build.sh)
# Then e.g.: build/tools/corridor_eval --dataset=OUTPUT_DIR --sequence --threads=2
set -euo pipefail
OUT=${1:?usage: bash scripts/make_vga_sequences.sh OUTPUT_DIR}
SYNTH="$(dirname "$0")/../${BUILD_DIR:-build}/tools/corridor_synth"
[ -x "$SYNTH" ] || { echo "make_vga_sequences: $SYNTH not built (bash scripts/build.sh)" >&2; exit 1; }
mkdir -p "$OUT"
i=0
# width, ceiling, horizontal field of view, clutter, door density, contrast
for cfg in "1.6 2.4 70 0.3 0.6 0.9" "2.0 2.6 80 0.2 0.5 0.7" "2.4 2.8 90 0.4 0.4 0.8" \
           "2.8 3.0 60 0.1 0.7 0.6" "3.2 3.3 75 0.5 0.3 0.9" "1.8 2.5 85 0.3 0.8 0.5" \
           "2.2 2.7 65 0.6 0.5 0.85" "3.0 3.1 80 0.2 0.2 0.7"; do
  set -- $cfg
  i=$((i + 1))
  "$SYNTH" --preset=sequence --output_dir="$OUT" --scene_name="V$i" --frames=12 \
    --corridor_width="$1" --ceiling_height="$2" --hfov_deg="$3" --clutter="$4" \
    --door_density="$5" --contrast="$6" --seed=$((200 + i)) --yaw="0.0$((i % 5))" \
    --offset="0.$((i % 4))$((i % 3))" --pitch="0.0$((3 + i % 4))" >/dev/null
  echo "make_vga_sequences: V$i"
done
echo "make_vga_sequences: 8 scenes x 12 frames in $OUT"
