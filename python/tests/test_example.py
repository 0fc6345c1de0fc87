"""examples/depth_from_photo.py on a generated frame: its depth PNG is the module's depth."""

import os
import pathlib
import subprocess
import sys

import numpy as np

import corridor_depth as cd
from conftest import read_png16

EXAMPLE = pathlib.Path(os.environ["CORRIDOR_SOURCE_DIR"]) / "examples" / "depth_from_photo.py"


def test_example_writes_the_depth_and_the_figure(single_frame, tmp_path):
    image_path, camera_path, _ = single_frame
    run = subprocess.run([sys.executable, str(EXAMPLE), str(image_path), str(tmp_path),
                          "--camera", str(camera_path)], capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    mm = read_png16(tmp_path / "000000_depth.png").astype(np.float64)
    res = cd.recover_depth(cd.read_image(str(image_path)), cd.Camera.from_file(str(camera_path)))
    have = np.isfinite(res.depth)
    np.testing.assert_array_equal(have, mm > 0)
    assert np.abs(res.depth[have] * 1000 - mm[have]).max() <= 0.5 + 1e-3
    figure = tmp_path / "000000_figure.png"
    assert figure.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_example_without_a_height_is_bad_usage(single_frame, tmp_path):
    image_path, _, _ = single_frame
    run = subprocess.run([sys.executable, str(EXAMPLE), str(image_path), str(tmp_path),
                          "--hfov", "70"], capture_output=True, text=True)
    assert run.returncode == 2
    assert "--camera_height is required" in run.stderr
