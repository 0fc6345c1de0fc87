#!/usr/bin/env bash
# Renders the generator's real-buildings preset, one dataset per class (10 scenes x 20 frames,
# 640x480, seeds in synth/real_buildings.h): OUT/<class>/<class>_s<seed>/{rgb,depth,...}.
# With --eval, also runs corridor_eval --solver=joint on each class (single frames, one thread) into
# OUT/eval/<class>/ and prints the baseline table (scripts/real_buildings_table.py).
#   scripts/make_real_buildings.sh [--eval] [OUT (default data/real_buildings)] [BUILD (default build)]
set -euo pipefail
eval_too=0
if [[ "${1:-}" == "--eval" ]]; then eval_too=1; shift; fi
out=${1:-data/real_buildings}
build=${2:-build}
here=$(cd "$(dirname "$0")" && pwd)
classes="rail wainscot furniture floor carpet glass windows pillars head low mix glossy satin baseboard"
for c in $classes; do
  rm -rf "${out:?}/$c"
  "$build/tools/corridor_synth" --preset=real_buildings --real_class="$c" --output_dir="$out/$c" \
    2> /dev/null
done
if [[ $eval_too == 1 ]]; then
  mkdir -p "$out/eval"
  for c in $classes; do
    rm -rf "${out:?}/eval/$c"
    "$build/tools/corridor_eval" --dataset="$out/$c" --output_dir="$out/eval/$c" --solver=joint \
      --sequence=false --threads=1 --write_depth=false > "$out/eval/$c.log" 2>&1 || true
  done
  python3 "$here/real_buildings_table.py" "$out/eval" $classes
fi
