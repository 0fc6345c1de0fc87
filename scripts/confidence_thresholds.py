#!/usr/bin/env python3
"""What a frame-confidence threshold would refuse, from corridor_eval reports.

Usage: python3 scripts/confidence_thresholds.py EVAL_DIR [EVAL_DIR ...]
Each EVAL_DIR holds a report.csv written by corridor_eval with --min_confidence=0 (so that every
frame keeps its geometry and its confidence). A frame is right when its width is within 3% of the
truth and ok but wrong when it is more than 10% off; the table gives, for each threshold, the
right frames it would refuse and the ok-but-wrong frames it would leave.
"""
import csv
import os
import sys

THRESHOLDS = [0.3, 0.4, 0.5, 0.55, 0.6, 0.65, 0.7, 0.8]


def frames(eval_dir):
    with open(os.path.join(eval_dir, "report.csv"), newline="") as f:
        for row in csv.DictReader(f):
            if row["status"] != "ok" or not row["width_rel_error"]:
                continue
            yield abs(float(row["width_rel_error"])), float(row["confidence"])


def main(argv):
    if len(argv) < 2:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    right, wrong = [], []
    for eval_dir in argv[1:]:
        for error, confidence in frames(eval_dir):
            if error <= 0.03:
                right.append(confidence)
            elif error > 0.10:
                wrong.append(confidence)
    if not right:
        print("confidence_thresholds: no right frame in the reports", file=sys.stderr)
        return 1
    print("| threshold | right frames refused | ok but wrong (>10%) refused |")
    print("|---:|---:|---:|")
    for t in THRESHOLDS:
        refused_right = sum(c < t for c in right)
        refused_wrong = sum(c < t for c in wrong)
        print("| %.2f | %d of %d (%.1f%%) | %d of %d |" % (
            t, refused_right, len(right), 100.0 * refused_right / len(right), refused_wrong,
            len(wrong)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
