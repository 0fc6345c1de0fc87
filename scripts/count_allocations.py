#!/usr/bin/env python3
"""Heap allocations per frame of a corridor_benchmarks EndToEnd benchmark, by call site, under
callgrind.

Usage: python3 scripts/count_allocations.py [BENCHMARK] [--min_time=SECONDS] [--depth=D]
  BENCHMARK  one benchmark's full name, default EndToEnd/default/640x480
  --min_time Google Benchmark's, in valgrind's slowed time; default 1 (a few frames)
  --depth    callers kept per allocation (callgrind --separate-callers), default 6

Counts the calls of the allocation functions (malloc, calloc, realloc, posix_memalign,
aligned_alloc, memalign, operator new and new[]) made inside DepthRecoverer::Recover
(valgrind --toggle-collect), divided by the number of Recover calls, so that the warm-up frame
(run through Detect and Reconstruct) is left out: steady state. Each allocation is put down to
its call site: the innermost caller that is not the C or C++ runtime, not OpenCV, Ceres, glog or
Eigen, and not the standard library's templates, is the project's own code that asked for it; an
allocation whose chain passes through OpenCV or Ceres before reaching the project's code is that
library's ("inside cv::..."), listed with the project's function that called the library.
Needs valgrind and a build with -DCORRIDOR_BUILD_BENCHMARKS=ON (BUILD_DIR, default build).
Standard library only.
"""

import collections
import os
import re
import shutil
import subprocess
import sys
import tempfile

ALLOC = re.compile(r"^(malloc|calloc|realloc|posix_memalign|aligned_alloc|memalign|"
                   r"operator new(\[\])?\(.*\))$")
RECOVER = re.compile(r"DepthRecoverer::Recover\(")
NAMED = re.compile(r"^(c?fn)=\((\d+)\)(?: (.*))?$")
# Frames that are not the call site: the allocator, the runtime and the standard library's code.
RUNTIME = re.compile(r"^(std::|__gnu_cxx::|__|_int_|operator new|Eigen::|void std::|"
                     r"\?\?\?|0x[0-9a-f]+$)")
LIBRARY = re.compile(r"^(cv::|ceres::|google::|void cv::|void ceres::)")


def split_chain(name):
    """callgrind --separate-callers joins a function and its callers with a quote."""
    return name.split("'")


def short(name, width=110):
    name = name.replace("(anonymous namespace)", "{anonymous}")
    name = re.sub(r"\(.*", "(...)", name) if len(name) > width else name
    return name[:width]


def qualified_name(frame):
    """The function's qualified name without template arguments, parameters or return type
    (a template's demangled name starts with its return type: "cv::Vec<int, 4>& std::vector<...
    >::emplace_back<...>(...)" is std::vector's)."""
    depth, out = 0, []
    for ch in frame:
        if ch == "<":
            depth += 1
        elif ch == ">":
            depth = max(0, depth - 1)
        elif depth == 0:
            if ch == "(" and out and "".join(out).strip():
                name = "".join(out).strip()
                if not name.endswith("anonymous namespace"):
                    break
            out.append(ch)
    return "".join(out).split()[-1] if "".join(out).split() else frame


def site_of(chain):
    """(kind, site) of an allocation whose callers are chain (innermost first)."""
    for i, frame in enumerate(chain):
        frame_name = qualified_name(frame.replace("(anonymous namespace)", "{anonymous}"))
        if RUNTIME.match(frame_name):
            continue
        if LIBRARY.match(frame_name):
            owner = next((f for f in chain[i + 1:] if f.startswith("corridor::")), "?")
            return "library", f"inside {short(frame, 60)} <- {short(owner, 70)}"
        if frame_name.startswith("corridor::"):
            return "project", short(frame)
        return "other", short(frame)
    return "other", short(chain[-1] if chain else "?")


def count(path):
    names = {}
    per_site = collections.Counter()
    kinds = {}
    recover_calls = 0
    current = ""
    callee = ""
    with open(path, encoding="utf-8", errors="replace") as f:
        for line in f:
            line = line.rstrip("\n")
            match = NAMED.match(line)
            if match:
                kind, ident, name = match.groups()
                if name:
                    names[ident] = name
                if kind == "fn":
                    current = names.get(ident, "")
                else:
                    callee = names.get(ident, "")
                continue
            if not line.startswith("calls="):
                continue
            calls = int(line.split("=", 1)[1].split()[0])
            callee_chain = split_chain(callee)
            caller_chain = split_chain(current)
            if RECOVER.search(callee_chain[0]) and not RECOVER.search(caller_chain[0]):
                recover_calls += calls
            # An allocation function called from something that is not one itself.
            if ALLOC.match(callee_chain[0]) and not ALLOC.match(caller_chain[0]):
                kind, site = site_of(caller_chain)
                per_site[site] += calls
                kinds[site] = kind
    return recover_calls, per_site, kinds


def main(argv):
    name = "EndToEnd/default/640x480"
    min_time = 1.0
    depth = 6
    for arg in argv[1:]:
        if arg.startswith("--min_time="):
            min_time = float(arg.split("=", 1)[1])
        elif arg.startswith("--depth="):
            depth = int(arg.split("=", 1)[1])
        elif arg in ("-h", "--help"):
            print(__doc__)
            return 0
        else:
            name = arg
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    binary = os.path.join(root, os.environ.get("BUILD_DIR", "build"), "benchmarks",
                          "corridor_benchmarks")
    if not os.access(binary, os.X_OK):
        print(f"count_allocations: {binary} not built", file=sys.stderr)
        return 1
    if shutil.which("valgrind") is None:
        print("count_allocations: valgrind is not installed", file=sys.stderr)
        return 1
    with tempfile.TemporaryDirectory() as tmp:
        out_file = os.path.join(tmp, "callgrind.out")
        run = subprocess.run(
            ["valgrind", "--tool=callgrind", f"--callgrind-out-file={out_file}",
             "--toggle-collect=corridor::DepthRecoverer::Recover*",
             f"--separate-callers={depth}", binary,
             f"--benchmark_filter=^{re.escape(name)}$", f"--benchmark_min_time={min_time}"],
            capture_output=True, text=True)
        if run.returncode != 0 or not os.path.exists(out_file):
            print(f"count_allocations: valgrind failed: {run.stderr.strip().splitlines()[-3:]}",
                  file=sys.stderr)
            return 1
        recover_calls, per_site, kinds = count(out_file)
    if recover_calls == 0:
        print("count_allocations: no Recover call was collected", file=sys.stderr)
        return 1
    total = sum(per_site.values())
    print(f"{name}: {recover_calls} frames, {total / recover_calls:.1f} allocations per frame")
    for kind in ("project", "library", "other"):
        sites = [(s, n) for s, n in per_site.items() if kinds[s] == kind]
        if not sites:
            continue
        subtotal = sum(n for _, n in sites)
        print(f"\n| {kind} call site | per frame |\n|---|---:|")
        for site, n in sorted(sites, key=lambda x: (-x[1], x[0])):
            print(f"| {site} | {n / recover_calls:.1f} |")
        print(f"| total ({kind}) | {subtotal / recover_calls:.1f} |")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
