#!/usr/bin/env python3
"""Markdown table of corridor_benchmarks results (Google Benchmark JSON).

Usage: python3 scripts/benchmark_table.py [--cpu] FILE.json
  --cpu  the benchmarks' CPU time instead of their real time (on a machine shared with other
         work, real time also counts the time the benchmark waited for a core)

Reads the EndToEnd/<config>/<width>x<height> benchmarks and prints, per size, the median time per
frame of every config (the mean when the run had no repetitions), in milliseconds: paper, default,
best, both floors (floor: a colour Canny; floor_grey: the honest one, a grey Canny), then the
others; the ratios paper/default, paper/best, default/floor_grey, best/floor_grey and best/floor
(and paper/best_paper_scope, like for like, when that config ran), all from the same run; and
default's and best's width errors on the timed frame (their width_error_mm counters): a fast
answer is only worth its time if it is right. Standard library only.
"""

import json
import re
import statistics
import sys
from collections import defaultdict

NAME = re.compile(r"^EndToEnd/([^/]+)/(\d+)x(\d+)$")
TO_MS = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}
MAIN_CONFIGS = ["paper", "default", "best", "floor", "floor_grey"]
# (numerator, denominator) of each ratio column.
RATIOS = [("paper", "default"), ("paper", "best"), ("default", "floor_grey"),
          ("best", "floor_grey"), ("best", "floor")]
ERRORS = ["default", "best"]    # Configs whose width error is shown.


def load_times(path, field="real_time"):
    """{(config, (w, h)): milliseconds} from the JSON (`field`: real_time or cpu_time): medians of
    repetitions, else means."""
    with open(path, encoding="utf-8") as f:
        data = json.load(f)
    runs = defaultdict(list)      # Individual iterations-runs.
    aggregates = {}               # (key, aggregate name) -> ms, when Google Benchmark wrote them.
    width_errors = {}             # key -> the width_error_mm counter (the same in every run).
    for b in data.get("benchmarks", []):
        if b.get("error_occurred"):
            continue
        match = NAME.match(b.get("run_name", b["name"]))
        if not match:
            continue
        key = (match.group(1), (int(match.group(2)), int(match.group(3))))
        ms = b[field] * TO_MS[b.get("time_unit", "ns")]
        # Not from the stddev or cv aggregates, whose counters are spreads.
        if "width_error_mm" in b and b.get("aggregate_name", "median") in ("median", "mean"):
            width_errors[key] = b["width_error_mm"]
        if b.get("run_type") == "aggregate":
            aggregates[(key, b.get("aggregate_name"))] = ms
        else:
            runs[key].append(ms)
    times = {}
    for key in set(runs) | {k for k, _ in aggregates}:
        if (key, "median") in aggregates:
            times[key] = aggregates[(key, "median")]
        elif len(runs[key]) > 1:
            times[key] = statistics.median(runs[key])
        elif (key, "mean") in aggregates:
            times[key] = aggregates[(key, "mean")]
        elif runs[key]:
            times[key] = statistics.mean(runs[key])
    repeated = any(len(v) > 1 for v in runs.values()) or any(
        a == "median" for _, a in aggregates)
    return times, width_errors, repeated, data.get("context", {})


def ratio(a, b):
    return "-" if a is None or b is None or b == 0 else f"{a / b:.1f}x"


def fmt(ms):
    return "-" if ms is None else f"{ms:.2f}"


def fmt_mm(mm):
    return "-" if mm is None else f"{mm:.0f}"


def main(argv):
    cpu = "--cpu" in argv[1:]
    paths = [a for a in argv[1:] if a != "--cpu"]
    if len(paths) != 1:
        print(__doc__, file=sys.stderr)
        return 2
    path = paths[0]
    times, width_errors, repeated, context = load_times(path, "cpu_time" if cpu else "real_time")
    if not times:
        print(f"{path}: no EndToEnd/<config>/<width>x<height> results", file=sys.stderr)
        return 1
    sizes = sorted({size for _, size in times}, key=lambda s: s[0] * s[1])
    extra = sorted({c for c, _ in times} - set(MAIN_CONFIGS))
    configs = [c for c in MAIN_CONFIGS if any(k[0] == c for k in times)] + extra
    stat = "median" if repeated else "mean"
    clock = "CPU time" if cpu else "real time"
    print(f"Time per frame, ms ({stat} of {clock}; {context.get('num_cpus', '?')} CPUs "
          f"at {context.get('mhz_per_cpu', '?')} MHz, {context.get('date', '')})")
    print()
    # paper against best on the same scope (no ceiling or end wall), when that was run.
    ratios = RATIOS + ([("paper", "best_paper_scope")]
                       if any(k[0] == "best_paper_scope" for k in times) else [])
    print("| size | " + " | ".join(configs) + " | " +
          " | ".join(f"{a}/{b}" for a, b in ratios) + " | " +
          " | ".join(f"{c}'s width error, mm" for c in ERRORS) + " |")
    print("|---|" + "---:|" * (len(configs) + len(ratios) + len(ERRORS)))
    for size in sizes:
        row = [fmt(times.get((c, size))) for c in configs]
        row += [ratio(times.get((a, size)), times.get((b, size))) for a, b in ratios]
        row += [fmt_mm(width_errors.get((c, size))) for c in ERRORS]
        print(f"| {size[0]}x{size[1]} | " + " | ".join(row) + " |")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
