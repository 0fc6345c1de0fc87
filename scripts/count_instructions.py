#!/usr/bin/env python3
"""Instructions per frame of corridor_benchmarks' EndToEnd benchmarks, under callgrind.

Usage: python3 scripts/count_instructions.py [REGEX] [--min_time=SECONDS]
  REGEX       which benchmarks (Google Benchmark filter), default: paper, default, best,
              best_paper_scope, best_tracked and both floors at 640x480 (DEFAULT_FILTER)
  --min_time  per benchmark, in valgrind's slowed time; default 0.0001 (one timed frame) for a
              single frame, 2 for the drives (best_sequence, best_tracked: a few dozen frames)

Timings on a shared machine move by tens of per cent from run to run; instruction counts do not,
so they are what to compare across versions. Counts only inside the function that does one frame
(valgrind --toggle-collect): DepthRecoverer::Recover, or for the floors bench::FloorFrame and
bench::FloorGreyFrame; divided by the number of that function's calls read from callgrind's own
call counts (Google Benchmark may call a benchmark more than once while it sizes the run, so its
iteration count is not the number of frames). Needs valgrind and a build with
-DCORRIDOR_BUILD_BENCHMARKS=ON. Standard library only.
"""

import os
import re
import shutil
import subprocess
import sys
import tempfile

DEFAULT_FILTER = ("EndToEnd/(paper|default|best|best_paper_scope|best_tracked|floor|floor_grey)"
                  "/640x480$")
TOGGLE = "corridor::DepthRecoverer::Recover*"
RECOVER = re.compile(r"DepthRecoverer::Recover\(")
# The floors' per-frame functions (benchmarks/corridor_benchmarks.cc): (toggle, call pattern).
FLOOR_FRAMES = {
    "floor": ("corridor::bench::FloorFrame*", re.compile(r"bench::FloorFrame\(")),
    "floor_grey": ("corridor::bench::FloorGreyFrame*", re.compile(r"bench::FloorGreyFrame\(")),
}
NAMED = re.compile(r"^(c?fn)=\((\d+)\)(?: (.*))?$")


def recover_calls_and_total(path, frame=RECOVER):
    """(instructions collected, calls of the per-frame function (`frame`, a regex on its name;
    Recover by default) from outside it) from a callgrind file."""
    names = {}
    total = None
    calls = 0
    current_is_recover = False
    called_is_recover = False
    with open(path, encoding="utf-8", errors="replace") as f:
        for line in f:
            line = line.rstrip("\n")
            match = NAMED.match(line)
            if match:
                kind, ident, name = match.groups()
                if name:
                    names[ident] = name
                is_recover = bool(frame.search(names.get(ident, "")))
                if kind == "fn":
                    current_is_recover = is_recover
                else:
                    called_is_recover = is_recover
                continue
            if line.startswith("calls="):
                if called_is_recover and not current_is_recover:
                    calls += int(line.split("=", 1)[1].split()[0])
                called_is_recover = False
            elif line.startswith("totals:") or (total is None and line.startswith("summary:")):
                total = int(line.split(":", 1)[1].split()[0])
    return total, calls


def list_benchmarks(binary, regex):
    out = subprocess.run([binary, "--benchmark_list_tests", f"--benchmark_filter={regex}"],
                         check=True, capture_output=True, text=True).stdout
    return [name for name in out.split() if name]


def main(argv):
    regex = DEFAULT_FILTER
    min_time = None
    for arg in argv[1:]:
        if arg.startswith("--min_time="):
            min_time = float(arg.split("=", 1)[1])
        elif arg in ("-h", "--help"):
            print(__doc__)
            return 0
        else:
            regex = arg
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    binary = os.path.join(root, os.environ.get("BUILD_DIR", "build"), "benchmarks",
                          "corridor_benchmarks")
    if not os.access(binary, os.X_OK):
        print(f"count_instructions: {binary} not built "
              "(bash scripts/build.sh -DCORRIDOR_BUILD_BENCHMARKS=ON)", file=sys.stderr)
        return 1
    if shutil.which("valgrind") is None:
        print("count_instructions: valgrind is not installed (apt-get install valgrind)",
              file=sys.stderr)
        return 1
    names = list_benchmarks(binary, regex)
    if not names:
        print(f"count_instructions: no benchmark matches {regex!r}", file=sys.stderr)
        return 1
    print("| benchmark | frames | instructions per frame |")
    print("|---|---:|---:|")
    with tempfile.TemporaryDirectory() as tmp:
        for name in names:
            drive = "best_sequence" in name or "best_tracked" in name
            seconds = min_time if min_time is not None else (2.0 if drive else 0.0001)
            out_file = os.path.join(tmp, "callgrind.out")
            toggle, frame = FLOOR_FRAMES.get(name.split("/")[1], (TOGGLE, RECOVER))
            run = subprocess.run(
                ["valgrind", "--tool=callgrind", f"--callgrind-out-file={out_file}",
                 f"--toggle-collect={toggle}", binary, f"--benchmark_filter=^{re.escape(name)}$",
                 f"--benchmark_min_time={seconds}"], capture_output=True, text=True)
            if run.returncode != 0 or not os.path.exists(out_file):
                print(f"| {name} | - | valgrind failed: {run.stderr.strip().splitlines()[-1:]} |")
                continue
            total, calls = recover_calls_and_total(out_file, frame)
            if not total or calls == 0:
                print(f"| {name} | 0 | - |")
            else:
                print(f"| {name} | {calls} | {total / calls / 1e6:.2f} M |")
            sys.stdout.flush()
            os.remove(out_file)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
