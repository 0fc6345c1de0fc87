#!/usr/bin/env python3
"""What the Python binding adds to a frame: the same image through RecoverDepth in C++
(corridor_python_reference, its own timer around the calls) and through
corridor_depth.recover_depth (timed here), in interleaved rounds of one run.

    PYTHONPATH=build/python python3 python/benchmarks/binding_overhead.py --build_dir build \\
        [--image IMAGE --camera CAMERA.yaml] [--rounds 7 --calls 100] [--callgrind]

Without --image, corridor_synth generates a 640x480 frame. Prints per round the mean
milliseconds per call of each and their ratio, then the medians. Timings on a shared machine
move by tens of per cent; with --callgrind, instructions are counted too (valgrind): each side's
whole process with 1 call and with 1 + K calls, the difference over K being the instructions
of one call, the interpreter's and the binding's included.
"""

import argparse
import pathlib
import statistics
import subprocess
import sys
import tempfile
import time

import corridor_depth as cd

PY_CALLS = """
import sys
import corridor_depth as cd
image = cd.read_image(sys.argv[1])
camera = cd.Camera.from_file(sys.argv[2])
for _ in range(int(sys.argv[3])):
    cd.recover_depth(image, camera)
"""


def instructions(command):
    """Instructions of a whole process under callgrind."""
    with tempfile.TemporaryDirectory() as tmp:
        out = f"{tmp}/callgrind.out"
        subprocess.run(["valgrind", "--tool=callgrind", f"--callgrind-out-file={out}", *command],
                       check=True, capture_output=True)
        for line in open(out, encoding="utf-8", errors="replace"):
            if line.startswith(("summary:", "totals:")):
                return int(line.split()[1])
    raise RuntimeError("no totals in callgrind's output")


def per_call_instructions(build, image_path, camera_path, height, extra):
    """(C++, Python) instructions per call: (3 + extra calls) - (3 calls), over extra."""
    def cpp(n):  # n > 2 calls: one untimed, n - 1 timed
        return instructions([str(build / "python" / "corridor_python_reference"), image_path,
                             camera_path, str(height), "/dev/null", str(n - 1)])

    def py(n):
        return instructions([sys.executable, "-c", PY_CALLS, image_path, camera_path, str(n)])

    return ((cpp(3 + extra) - cpp(3)) / extra, (py(3 + extra) - py(3)) / extra)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--build_dir", default="build")
    parser.add_argument("--image")
    parser.add_argument("--camera")
    parser.add_argument("--rounds", type=int, default=7)
    parser.add_argument("--calls", type=int, default=100)
    parser.add_argument("--callgrind", type=int, default=0, metavar="K",
                        help="also count instructions of K calls under callgrind (0 = no)")
    args = parser.parse_args()
    build = pathlib.Path(args.build_dir)
    with tempfile.TemporaryDirectory() as tmp:
        image_path, camera_path = args.image, args.camera
        if image_path is None:
            subprocess.run([str(build / "tools" / "corridor_synth"), "--preset=single",
                            f"--output_dir={tmp}", "--scene_name=corridor"], check=True,
                           capture_output=True)
            image_path = f"{tmp}/corridor/rgb/000000.png"
            camera_path = f"{tmp}/corridor/camera.yaml"
        camera = cd.Camera.from_file(camera_path)
        image = cd.read_image(image_path)
        print(f"image {image.shape[1]}x{image.shape[0]}, {args.calls} calls per round")
        assert cd.recover_depth(image, camera).ok
        cpp_ms, py_ms = [], []
        for round_index in range(args.rounds):
            run = subprocess.run([str(build / "python" / "corridor_python_reference"),
                                  image_path, camera_path, str(camera.camera_height),
                                  f"{tmp}/depth.raw", str(args.calls)],
                                 check=True, capture_output=True, text=True)
            values = dict(line.split("=", 1) for line in run.stdout.splitlines())
            cpp_ms.append(1000 * float(values["seconds_per_call"]))
            start = time.perf_counter()
            for _ in range(args.calls):
                cd.recover_depth(image, camera)
            py_ms.append(1000 * (time.perf_counter() - start) / args.calls)
            print(f"round {round_index}: C++ {cpp_ms[-1]:.3f} ms, Python {py_ms[-1]:.3f} ms, "
                  f"Python/C++ {py_ms[-1] / cpp_ms[-1]:.3f}")
        cpp, py = statistics.median(cpp_ms), statistics.median(py_ms)
        print(f"median: C++ {cpp:.3f} ms, Python {py:.3f} ms, Python/C++ {py / cpp:.3f} "
              f"(+{100 * (py / cpp - 1):.1f}%)")
        print(f"best:   C++ {min(cpp_ms):.3f} ms, Python {min(py_ms):.3f} ms, "
              f"Python/C++ {min(py_ms) / min(cpp_ms):.3f}")
        if args.callgrind:
            cpp_i, py_i = per_call_instructions(build, image_path, camera_path,
                                                camera.camera_height, args.callgrind)
            print(f"instructions per call: C++ {cpp_i / 1e6:.3f} M, Python {py_i / 1e6:.3f} M, "
                  f"Python/C++ {py_i / cpp_i:.4f} (+{100 * (py_i / cpp_i - 1):.2f}%)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
