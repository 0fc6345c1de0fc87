"""Camera: from intrinsics, a field of view and a calibration file, checked by hand."""

import math

import numpy as np

import corridor_depth as cd


def test_version_is_the_projects():
    import os
    import re
    cmake = open(os.path.join(os.environ["CORRIDOR_SOURCE_DIR"], "CMakeLists.txt")).read()
    assert cd.__version__ == re.search(r"project\(corridor_depth VERSION ([\d.]+)", cmake)[1]


def test_from_hfov():
    cam = cd.Camera.from_hfov(60.0, 640, 480)
    fx = 320.0 / math.tan(math.radians(30.0))  # Half the width over tan(hfov / 2).
    assert abs(cam.fx - fx) < 1e-9 and abs(cam.fy - fx) < 1e-9
    # Pixel centres at integers: the centre of a 640 x 480 image is (319.5, 239.5).
    assert (cam.cx, cam.cy) == (319.5, 239.5)
    assert (cam.image_width, cam.image_height) == (640, 480)
    assert cam.camera_height == 0.0
    assert abs(cam.hfov - 60.0) < 1e-9


def test_from_intrinsics():
    cam = cd.Camera(500.0, 510.0, 300.0, 200.0, 600, 400, camera_height=1.1,
                    distortion=[0.1, 0, 0, 0, 0])
    assert (cam.fx, cam.fy, cam.cx, cam.cy) == (500.0, 510.0, 300.0, 200.0)
    assert cam.camera_height == 1.1
    assert list(cam.distortion) == [0.1, 0, 0, 0, 0]


CAMERA_YAML = """image_width: 320
image_height: 240
camera_name: test
camera_matrix:
  rows: 3
  cols: 3
  data: [250.5, 0, 160.25, 0, 251.5, 119.75, 0, 0, 1]
distortion_model: plumb_bob
distortion_coefficients:
  rows: 1
  cols: 5
  data: [0, 0, 0, 0, 0]
camera_height: 0.75
"""


def test_from_file(tmp_path):
    path = tmp_path / "camera.yaml"
    path.write_text(CAMERA_YAML)
    cam = cd.Camera.from_file(str(path))
    assert (cam.fx, cam.fy, cam.cx, cam.cy) == (250.5, 251.5, 160.25, 119.75)
    assert (cam.image_width, cam.image_height) == (320, 240)
    assert cam.camera_height == 0.75


def test_read_image_and_write_depth_png(tmp_path):
    from PIL import Image
    rgb = np.zeros((4, 5, 3), np.uint8)
    rgb[..., 0] = 200  # Red in RGB order.
    Image.fromarray(rgb).save(tmp_path / "red.png")
    bgr = cd.read_image(str(tmp_path / "red.png"))
    assert bgr.shape == (4, 5, 3) and bgr.dtype == np.uint8
    assert (bgr[..., 2] == 200).all() and (bgr[..., :2] == 0).all()
    # Without an EXIF orientation, upright reads the same pixels.
    np.testing.assert_array_equal(cd.read_image(str(tmp_path / "red.png"), upright=True), bgr)

    depth = np.array([[1.0, np.nan], [0.0, 2.0004]], np.float32)
    cd.write_depth_png(str(tmp_path / "depth.png"), depth)
    with Image.open(tmp_path / "depth.png") as image:
        mm = np.array(image, dtype=np.uint16)
    np.testing.assert_array_equal(mm, [[1000, 0], [0, 2000]])
