"""Sequence against the corridor_depth tool run on the same frames as a sequence."""

import subprocess

import numpy as np

import corridor_depth as cd
from conftest import read_png16, tool, truth_frames


def tool_sequence_flags():
    """--sequence=true where the tool has the flag (else it always runs folders in order)."""
    run = subprocess.run([tool("CORRIDOR_DEPTH_TOOL"), "--helpfull"], capture_output=True,
                         text=True)
    return ["--sequence=true"] if "-sequence" in run.stdout + run.stderr else []


def test_sequence_equals_the_tool_on_a_sequence(sequence_scene, tmp_path):
    subprocess.run([tool("CORRIDOR_DEPTH_TOOL"), f"--input={sequence_scene}",
                    f"--output_dir={tmp_path}", "--write_vis=false", *tool_sequence_flags()],
                   check=True, capture_output=True)
    camera = cd.Camera.from_file(str(sequence_scene / "camera.yaml"))
    seq = cd.Sequence()
    truth = truth_frames(sequence_scene)
    for frame in truth:
        res = seq.process(cd.read_image(str(sequence_scene / "rgb" / frame["file"])), camera)
        assert res.ok, res.status
        assert abs(res.geometry.width - frame["width"]) < 0.05
        tool_mm = read_png16(tmp_path / "corridor" / "depth" / frame["file"]).astype(np.float64)
        have = np.isfinite(res.depth)
        np.testing.assert_array_equal(have, tool_mm > 0)
        assert np.abs(res.depth[have] * 1000.0 - tool_mm[have]).max() <= 1.0


def test_reset_starts_a_new_sequence(sequence_scene):
    camera = cd.Camera.from_file(str(sequence_scene / "camera.yaml"))
    frames = [cd.read_image(str(p)) for p in sorted((sequence_scene / "rgb").glob("*.png"))]
    fresh = cd.Sequence(solver="joint").process(frames[0], camera)
    seq = cd.Sequence(solver="joint")
    for image in frames[:3]:
        seq.process(image, camera)
    seq.reset()
    again = seq.process(frames[0], camera)
    assert not again.junctions_tracked
    np.testing.assert_array_equal(again.depth, fresh.depth)
    assert again.geometry.width == fresh.geometry.width


def test_camera_height_given_to_the_sequence(sequence_scene):
    camera = cd.Camera.from_file(str(sequence_scene / "camera.yaml"))
    image = cd.read_image(str(sequence_scene / "rgb" / "000000.png"))
    own = cd.Sequence().process(image, camera)
    doubled = cd.Sequence(camera_height=2 * camera.camera_height).process(image, camera)
    assert own.ok and doubled.ok
    assert abs(doubled.geometry.width - 2 * own.geometry.width) < 1e-6 * own.geometry.width
