#!/usr/bin/env bash
# Runs corridor_depth on the eleven real photographs of tests/data/real-corridors/ with the
# cameras their README gives (popup_1: its uEye calibration; popup_2/3: the Kinect default;
# rtabmap_*: --hfov=60), a 1.0 m camera height, prints the floor IoU of the three labelled frames,
# and tiles the result panels into docs/real_photos_contact_sheet.png (Python 3 with PIL).
# Usage: bash scripts/real_photos.sh [BUILD_DIR] [OUT_DIR]
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
BUILD="${1:-$ROOT/build}"
OUT="${2:-$ROOT/out/real_photos}"
PHOTOS="$ROOT/tests/data/real-corridors"
TOOL="$BUILD/tools/corridor_depth"
[ -x "$TOOL" ] || { echo "real_photos: build corridor_depth first ($TOOL)" >&2; exit 2; }
rm -rf "$OUT"
mkdir -p "$OUT/in/popup_1" "$OUT/in/kinect" "$OUT/in/rtabmap"
cp "$PHOTOS/popup_1.png" "$OUT/in/popup_1/"
cp "$PHOTOS/popup_2.png" "$PHOTOS/popup_3.png" "$OUT/in/kinect/"
cp "$PHOTOS"/rtabmap_*.jpg "$OUT/in/rtabmap/"
common=(--output_dir="$OUT/depth" --camera_height=1.0 --write_floor_mask)
# A photo without a corridor found is a result too (corridor_depth exits 1 and says which): the
# rest still run, and the sheet shows its reason.
run() { "$TOOL" "$@" "${common[@]}" || [ $? -eq 1 ]; }
run --input="$OUT/in/popup_1" --fx=371.975 --fy=372.164 --cx=315.632 --cy=250.593
run --input="$OUT/in/kinect" --fx=570.342 --cx=319.5 --cy=239.5
run --input="$OUT/in/rtabmap" --hfov=60
PYTHON=/usr/bin/python3
"$PYTHON" - "$OUT/depth" "$PHOTOS" "$ROOT/docs/real_photos_contact_sheet.png" <<'PY'
import glob, os, sys
from PIL import Image
depth, photos, sheet_path = sys.argv[1:4]
print("| photo | floor IoU |\n|---|---|")
for name, folder in (("popup_1", "popup_1"), ("popup_2", "kinect"), ("popup_3", "kinect")):
    mask = os.path.join(depth, folder, "floor", name + ".png")
    if not os.path.exists(mask):
        print("| %s | no corridor found |" % name)
        continue
    pred = Image.open(mask).convert("L")
    label = Image.open(os.path.join(photos, name + "_floor.png")).convert("L")
    p, l = pred.load(), label.load()
    inter = union = 0
    for y in range(pred.size[1]):
        for x in range(pred.size[0]):
            a, b = p[x, y] > 127, l[x, y] > 127
            inter += a and b
            union += a or b
    print("| %s | %.3f |" % (name, inter / union))
panels = sorted(glob.glob(os.path.join(depth, "*", "vis", "*.png")))
tiles = []
for path in panels:
    im = Image.open(path).convert("RGB")
    tiles.append(im.resize((640, int(im.size[1] * 640 / im.size[0]))))
cols = 3
rows = (len(tiles) + cols - 1) // cols
h = max(t.size[1] for t in tiles)
sheet = Image.new("RGB", (cols * 640, rows * h), (0, 0, 0))
for i, t in enumerate(tiles):
    sheet.paste(t, ((i % cols) * 640, (i // cols) * h))
sheet.save(sheet_path)
print("contact sheet of %d photos: %s" % (len(tiles), sheet_path))
PY
