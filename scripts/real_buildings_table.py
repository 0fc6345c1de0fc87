#!/usr/bin/env python3
"""Baseline table of the real-buildings preset from corridor_eval's report.csv files.

usage: real_buildings_table.py EVAL_ROOT CLASS...   (reads EVAL_ROOT/<class>/report.csv)

Per class: frames; ok; width within 3% (ok and |width error| <= 3%: refused and failed frames
count as misses); ok but wrong (ok and width off by more than 10%); refused (no corridor found,
implausible geometry, low confidence); failed (any other error); mean |width error| and mean
AbsRel of depth < 5 m, both over the ok frames. Prints a Markdown table.
"""
import csv
import os
import sys

REFUSED = ("no corridor found", "no_corridor_found", "implausible geometry",
           "implausible_geometry", "low confidence", "low_confidence")


def summarise(path):
    rows = list(csv.DictReader(open(path, newline="")))
    config = rows[0]["config"] if rows else ""
    rows = [r for r in rows if r["config"] == config]  # The first configuration only.
    n = len(rows)
    ok = [r for r in rows if r["status"] == "ok"]
    refused = [r for r in rows if r["status"] != "ok" and r["reason"].lower().startswith(REFUSED)]
    errors = [abs(float(r["width_rel_error"])) for r in ok if r["width_rel_error"]]
    absrel = [float(r["lt5_abs_rel"]) for r in ok if r.get("lt5_abs_rel")]
    return {
        "frames": n,
        "ok": len(ok),
        "within3": sum(e <= 0.03 for e in errors),
        "wrong": sum(e > 0.10 for e in errors),
        "refused": len(refused),
        "failed": n - len(ok) - len(refused),
        "width_err": sum(errors) / len(errors) if errors else float("nan"),
        "absrel": sum(absrel) / len(absrel) if absrel else float("nan"),
    }


def pct(k, n):
    return f"{k} ({100.0 * k / n:.1f}%)" if n else str(k)


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    root = sys.argv[1]
    print("| class | frames | ok | width within 3% | ok but wrong (>10%) | refused | failed "
          "| mean width error (ok) | AbsRel < 5 m (ok) |")
    print("|---|---|---|---|---|---|---|---|---|")
    for name in sys.argv[2:]:
        path = os.path.join(root, name, "report.csv")
        if not os.path.exists(path):
            print(f"| {name} | missing | | | | | | | |")
            continue
        s = summarise(path)
        n = s["frames"]
        print(f"| {name} | {n} | {pct(s['ok'], n)} | {pct(s['within3'], n)} | "
              f"{pct(s['wrong'], n)} | {pct(s['refused'], n)} | {pct(s['failed'], n)} | "
              f"{100 * s['width_err']:.1f}% | {s['absrel']:.3f} |")


if __name__ == "__main__":
    main()
