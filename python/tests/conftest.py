"""Shared fixtures: the tools' paths (from ctest's environment) and generated frames."""

import os
import pathlib
import subprocess

import numpy as np
import pytest
from PIL import Image


def tool(variable):
    """A program whose path ctest passes in `variable` (python/CMakeLists.txt)."""
    path = os.environ.get(variable)
    assert path, f"{variable} is not set: run the tests through ctest (label python)"
    assert os.access(path, os.X_OK), f"{variable}={path} is not an executable"
    return path


def read_png16(path):
    """A 16-bit PNG as uint16, read by PIL (not by the module under test)."""
    with Image.open(path) as image:
        return np.array(image, dtype=np.uint16)


def synthesize(out_dir, *extra):
    """corridor_synth into out_dir; returns the scene folder."""
    subprocess.run([tool("CORRIDOR_SYNTH"), f"--output_dir={out_dir}", "--scene_name=corridor",
                    *extra], check=True, capture_output=True)
    return pathlib.Path(out_dir) / "corridor"


def truth_frames(scene):
    """The generator's truth.yaml as a list of dicts of floats (its simple layout only)."""
    frames, current = [], None
    for line in (scene / "truth.yaml").read_text().splitlines():
        text = line.strip()
        if text.startswith("- file:"):
            current = {"file": text.split(":", 1)[1].strip()}
            frames.append(current)
        elif current is not None and ":" in text:
            key, value = (part.strip() for part in text.split(":", 1))
            current[key] = float(value)
    return frames


@pytest.fixture(scope="module")  # ctest runs each test file in its own pytest
def single_frame(tmp_path_factory):
    """One generated 640x480 corridor frame: (image path, camera.yaml path, truth dict)."""
    scene = synthesize(tmp_path_factory.mktemp("single"), "--preset=single")
    return scene / "rgb" / "000000.png", scene / "camera.yaml", truth_frames(scene)[0]


@pytest.fixture(scope="module")  # ctest runs each test file in its own pytest
def sequence_scene(tmp_path_factory):
    """A generated sequence of 6 frames: the scene folder."""
    return synthesize(tmp_path_factory.mktemp("sequence"), "--preset=sequence", "--frames=6")
