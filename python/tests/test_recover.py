"""recover_depth against the C++ paths: the tool's PNG and RecoverDepth's float depth."""

import subprocess
import sys
import threading
import time

import numpy as np

import corridor_depth as cd
from conftest import read_png16, tool
from corridor_by_hand import rotation


def test_depth_equals_the_tools_png_within_a_millimetre(single_frame, tmp_path):
    image_path, camera_path, _ = single_frame
    subprocess.run([tool("CORRIDOR_DEPTH_TOOL"), f"--input={image_path}",
                    f"--camera={camera_path}", f"--output_dir={tmp_path}", "--write_vis=false"],
                   check=True, capture_output=True)
    (png,) = tmp_path.glob("*/depth/000000.png")
    tool_mm = read_png16(png).astype(np.float64)

    res = cd.recover_depth(cd.read_image(str(image_path)), cd.Camera.from_file(str(camera_path)))
    assert res.ok, res.status
    assert res.depth.dtype == np.float32 and res.depth.shape == tool_mm.shape
    have = np.isfinite(res.depth)
    np.testing.assert_array_equal(have, tool_mm > 0)
    assert have.mean() > 0.8
    assert np.abs(res.depth[have] * 1000.0 - tool_mm[have]).max() <= 1.0


def reference(image_path, camera, height, out_raw):
    """The float depth and geometry of RecoverDepth through corridor_python_reference."""
    run = subprocess.run([tool("CORRIDOR_PYTHON_REFERENCE"), str(image_path), str(camera),
                          str(height), str(out_raw)], capture_output=True, text=True)
    values = dict(line.split("=", 1) for line in run.stdout.splitlines())
    rows, cols = int(values["rows"]), int(values["cols"])
    depth = np.fromfile(out_raw, dtype=np.float32).reshape(rows, cols)
    return depth, values


def test_float_depth_and_geometry_equal_recover_depths(single_frame, tmp_path):
    image_path, camera_path, truth = single_frame
    ref, values = reference(image_path, camera_path, 0.8, tmp_path / "depth.raw")
    assert values["status"] == "ok"
    camera = cd.Camera.from_file(str(camera_path))
    res = cd.recover_depth(cd.read_image(str(image_path)), camera, camera_height=0.8)
    assert res.ok
    # The reference writes 0 for no estimate; the module NaN.
    np.testing.assert_array_equal(np.isfinite(res.depth), ref > 0)
    have = ref > 0
    assert np.abs(res.depth[have] - ref[have]).max() <= 1e-6
    for name in ("yaw", "pitch", "offset", "width", "ceiling_height"):
        assert abs(getattr(res.geometry, name) - float(values[name])) <= 1e-9, name
    # camera_height overrode the file's 0.66 m: the generated corridor scales by 0.8 / 0.66.
    assert abs(res.geometry.width - truth["width"] * 0.8 / truth["camera_height"]) < 0.05


def test_result_fields(single_frame):
    image_path, camera_path, truth = single_frame
    image = cd.read_image(str(image_path))
    res = cd.recover_depth(image, cd.Camera.from_file(str(camera_path)), solver="lm")
    assert res.ok and res.status.ok and res.status.code == "ok"
    assert res.status.status_class == "ok"
    assert res.has_geometry
    assert abs(res.geometry.width - truth["width"]) < 0.05
    assert abs(res.geometry.pitch - truth["pitch"]) < 0.01
    assert abs(res.geometry.camera_height - truth["camera_height"]) < 1e-12
    assert res.solver_summary.solver_name == "lm"
    left, right = res.junctions.left, res.junctions.right
    assert res.junctions.found
    # The left junction runs from the bottom left up toward the vanishing point, the right one
    # from the bottom right.
    assert left.near_end[0] < left.far_end[0] and left.near_end[1] > left.far_end[1]
    assert right.near_end[0] > right.far_end[0] and right.near_end[1] > right.far_end[1]
    for line in (left, right):
        a, b, c = line.line
        for u, v in (line.near_end, line.far_end):
            assert abs(a * u + b * v + c) < 1.0
    assert set(res.times) == {"perception", "solve", "ceiling", "end_wall", "rasterize", "total"}
    assert res.times["total"] > 0


def true_junction_line(truth, camera, x_wall):
    """The image line (a, b, c), a^2 + b^2 = 1, of the generator's junction X_W = x_wall."""
    r = rotation(truth["yaw"], truth["pitch"])
    ends = []
    for s in (2.0, 20.0):
        p = r @ np.array([x_wall, truth["camera_height"], s])
        ends.append(np.array([camera.fx * p[0] / p[2] + camera.cx,
                              camera.fy * p[1] / p[2] + camera.cy, 1.0]))
    line = np.cross(ends[0], ends[1])
    return line / np.hypot(line[0], line[1])


def test_edge_points_lie_on_the_true_junctions(single_frame):
    image_path, camera_path, truth = single_frame
    camera = cd.Camera.from_file(str(camera_path))
    image = cd.read_image(str(image_path))
    res = cd.recover_depth(image, camera)
    assert res.ok
    half, offset = truth["width"] / 2, truth["offset"]
    for line, x_wall in ((res.junctions.left, -(half + offset)),
                         (res.junctions.right, half - offset)):
        points, weights = line.edge_points, line.edge_weights
        assert points.dtype == np.float64 and points.ndim == 2 and points.shape[1] == 2
        assert len(points) >= 30 and weights.shape == (len(points),)
        assert (weights > 0).all() and abs(weights.mean() - 1.0) < 1e-9
        true_line = true_junction_line(truth, camera, x_wall)
        distance = np.abs(points @ true_line[:2] + true_line[2])
        assert np.median(distance) < 0.5 and np.percentile(distance, 90) < 1.5
    # Fitting the lines' own points, the solver is given no edge points.
    lines = cd.recover_depth(image, camera, solver_evidence="lines")
    assert lines.junctions.left.edge_points.shape == (0, 2)
    assert lines.junctions.right.edge_weights.shape == (0,)


def test_rgb_keyword_and_grey_input(single_frame):
    image_path, camera_path, _ = single_frame
    bgr = cd.read_image(str(image_path))
    camera = cd.Camera.from_file(str(camera_path))
    expected = cd.recover_depth(bgr, camera).depth
    from_rgb = cd.recover_depth(np.ascontiguousarray(bgr[:, :, ::-1]), camera, rgb=True).depth
    np.testing.assert_array_equal(from_rgb, expected)
    # A non-contiguous view is accepted as well.
    np.testing.assert_array_equal(cd.recover_depth(bgr[:, :, ::-1], camera, rgb=True).depth,
                                  expected)
    grey = cd.recover_depth(bgr.mean(axis=2).astype(np.uint8), camera)
    assert grey.depth.shape == bgr.shape[:2] and grey.depth.dtype == np.float32


def test_a_frame_without_a_corridor_is_refused_not_raised(single_frame):
    _, camera_path, _ = single_frame
    camera = cd.Camera.from_file(str(camera_path))
    blank = np.full((camera.image_height, camera.image_width, 3), 128, np.uint8)
    res = cd.recover_depth(blank, camera)
    assert not res.ok
    assert res.status.code == "no_corridor_found"
    assert res.status.status_class == "refused"
    assert res.status.message
    assert res.depth.shape == blank.shape[:2] and np.isnan(res.depth).all()


def test_the_call_releases_the_gil(single_frame):
    """A second Python thread counts while recover_depth runs. The switch interval is made so
    long that the counting thread can only run when the main thread lets go of the GIL. The
    controls, a pure Python loop and a module call that keeps the GIL (depth_metrics on large
    images), let it count nothing."""
    image_path, camera_path, _ = single_frame
    image = cd.read_image(str(image_path))
    camera = cd.Camera.from_file(str(camera_path))
    cd.recover_depth(image, camera)  # Warm up (first-call initialisation).
    count = [0]
    stop = threading.Event()

    def counter():
        while not stop.is_set():
            count[0] += 1
            time.sleep(0.0001)

    def held_gil():
        total = 0
        for i in range(2_000_000):
            total += i
        return total

    interval = sys.getswitchinterval()
    sys.setswitchinterval(100.0)
    worker = threading.Thread(target=counter)
    try:
        worker.start()
        time.sleep(0.01)  # Let the counter start.
        before = count[0]
        held_gil()
        during_python = count[0] - before
        big = np.ones((1000, 1000), np.float32)
        before = count[0]
        cd.depth_metrics(big, big)
        during_metrics = count[0] - before
        # Calls until the counter has moved on, at most 50: on a loaded machine the counting
        # thread may get little of a single call.
        before = count[0]
        for _ in range(50):
            cd.recover_depth(image, camera)
            if count[0] - before > 10:
                break
        during_recover = count[0] - before
    finally:
        stop.set()
        worker.join()
        sys.setswitchinterval(interval)
    assert during_python == 0
    assert during_metrics == 0
    assert during_recover > 10


def test_options_by_field_and_flag_name(single_frame):
    image_path, camera_path, _ = single_frame
    image = cd.read_image(str(image_path))
    camera = cd.Camera.from_file(str(camera_path))
    near = cd.recover_depth(image, camera, max_range=5.0)  # The tools' flag name.
    assert near.ok and np.nanmax(near.depth) <= 5.0
    full = cd.recover_depth(image, camera)
    assert np.nanmax(full.depth) > 5.0
    # A tool flag and the RecoverDepthOptions field it stands for give the same result.
    by_flag = cd.recover_depth(image, camera, end_wall=False, inner_line_check=False)
    by_field = cd.recover_depth(image, camera, estimate_end_wall=False,
                                ceiling_checks_inner_lines=False)
    np.testing.assert_array_equal(by_flag.depth, by_field.depth)
    assert not by_flag.end_wall_found
    assert {"solver", "max_range", "roi_top", "hough_angle_window"} <= set(cd.option_names())


def rolled(image, degrees):
    """The image as a camera turned by `degrees` about its optical axis (through the image's
    centre, which is the principal point of the generated frames) would see it: bilinear."""
    rows, cols = image.shape[:2]
    cy, cx = (rows - 1) / 2, (cols - 1) / 2
    v, u = np.mgrid[0:rows, 0:cols].astype(np.float64)
    a = np.radians(degrees)
    # The level image's pixel that lands on (u, v): turned back by -a.
    x = np.cos(a) * (u - cx) + np.sin(a) * (v - cy) + cx
    y = -np.sin(a) * (u - cx) + np.cos(a) * (v - cy) + cy
    x0 = np.clip(np.floor(x).astype(int), 0, cols - 2)
    y0 = np.clip(np.floor(y).astype(int), 0, rows - 2)
    fx = np.clip(x - x0, 0, 1)[..., None]
    fy = np.clip(y - y0, 0, 1)[..., None]
    img = image.astype(np.float64)
    top = img[y0, x0] * (1 - fx) + img[y0, x0 + 1] * fx
    bottom = img[y0 + 1, x0] * (1 - fx) + img[y0 + 1, x0 + 1] * fx
    return np.ascontiguousarray(np.round(top * (1 - fy) + bottom * fy).astype(np.uint8))


def test_a_rolled_frame_reports_its_roll(single_frame):
    image_path, camera_path, _ = single_frame
    image = cd.read_image(str(image_path))
    camera = cd.Camera.from_file(str(camera_path))
    level = cd.recover_depth(image, camera)
    assert level.ok and abs(level.roll) < np.radians(0.3)
    turned = {}
    for degrees in (2.0, -2.0):
        res = cd.recover_depth(rolled(image, degrees), camera)
        assert res.ok, res.status
        assert abs(abs(res.roll) - np.radians(2.0)) < np.radians(0.3), res.roll
        assert cd.recover_depth(rolled(image, degrees), camera, level_roll=False).roll == 0
        turned[degrees] = res.roll
    assert turned[2.0] * turned[-2.0] < 0  # The roll found follows the turn's direction.


def test_min_confidence_refuses_frames_below_it(single_frame):
    image_path, camera_path, _ = single_frame
    image = cd.read_image(str(image_path))
    camera = cd.Camera.from_file(str(camera_path))
    res = cd.recover_depth(image, camera)
    assert res.ok and 0 < res.confidence <= 1
    below = cd.recover_depth(image, camera, min_confidence=max(0.0, res.confidence - 0.05))
    assert below.ok and below.confidence == res.confidence
    if res.confidence < 1:
        above = cd.recover_depth(image, camera, min_confidence=min(1.0, res.confidence + 0.05))
        assert not above.ok
        assert above.status.code == "low_confidence"
        assert above.status.status_class == "refused"
        assert np.isnan(above.depth).all()
    else:  # The generated frame is as sure as can be: nothing refuses it.
        assert cd.recover_depth(image, camera, min_confidence=1.0).ok
