"""Bad inputs raise, with the status message; unknown keywords raise TypeError naming them."""

import numpy as np
import pytest

import corridor_depth as cd

CAMERA = cd.Camera.from_hfov(60.0, 64, 48)
IMAGE = np.zeros((48, 64, 3), np.uint8)


def test_empty_image():
    with pytest.raises(ValueError, match="image is empty"):
        cd.recover_depth(np.zeros((0, 0, 3), np.uint8), CAMERA, camera_height=1.0)


def test_camera_of_another_size():
    with pytest.raises(ValueError, match="image is 32x24 but the calibration is for 64x48"):
        cd.recover_depth(np.zeros((24, 32, 3), np.uint8), CAMERA, camera_height=1.0)


def test_negative_height():
    with pytest.raises(ValueError, match=r"camera height -1 m must be in \(0, 10\] m"):
        cd.recover_depth(IMAGE, CAMERA, camera_height=-1.0)


def test_missing_height():
    with pytest.raises(ValueError, match="camera_height is required"):
        cd.recover_depth(IMAGE, CAMERA)
    with pytest.raises(ValueError, match="camera_height is required"):
        cd.Sequence().process(IMAGE, CAMERA)


def test_bad_option_values():
    with pytest.raises(ValueError, match="unknown solver 'nope'.*valid: grid"):
        cd.recover_depth(IMAGE, CAMERA, camera_height=1.0, solver="nope")
    with pytest.raises(ValueError, match=r"points_per_line must be in \[3, 10000\]"):
        cd.recover_depth(IMAGE, CAMERA, camera_height=1.0, points_per_line=1)
    with pytest.raises(ValueError, match="unknown solver"):
        cd.Sequence(solver="nope")


def test_unknown_keyword_and_wrong_type():
    with pytest.raises(TypeError, match="'max_rnage'"):
        cd.recover_depth(IMAGE, CAMERA, camera_height=1.0, max_rnage=20.0)
    with pytest.raises(TypeError, match="'bogus'"):
        cd.Sequence(bogus=1)
    with pytest.raises(TypeError, match="'points_per_line'"):
        cd.recover_depth(IMAGE, CAMERA, camera_height=1.0, points_per_line=2.5)
    with pytest.raises(TypeError, match="'loss_typo'"):
        cd.solve("lm", [[0, 40], [10, 30]], [[60, 40], [50, 30]], CAMERA, 1.0, loss_typo=1)


def test_image_types():
    with pytest.raises(ValueError, match="uint8 or uint16"):
        cd.recover_depth(IMAGE.astype(np.float32), CAMERA, camera_height=1.0)
    with pytest.raises(ValueError, match="HxW, HxWx3 or HxWx4"):
        cd.recover_depth(np.zeros((48, 64, 2), np.uint8), CAMERA, camera_height=1.0)
    with pytest.raises(ValueError, match="numpy array"):
        cd.recover_depth([[0]], CAMERA, camera_height=1.0)


def test_files(tmp_path):
    missing = str(tmp_path / "missing.png")
    with pytest.raises(FileNotFoundError, match="missing.png"):
        cd.read_image(missing)
    with pytest.raises(FileNotFoundError, match="missing.yaml"):
        cd.Camera.from_file(str(tmp_path / "missing.yaml"))
    not_an_image = tmp_path / "text.png"
    not_an_image.write_text("not a png")
    with pytest.raises(OSError, match="text.png"):
        cd.read_image(str(not_an_image))


def test_bad_cameras():
    with pytest.raises(ValueError, match="focal lengths"):
        cd.Camera(-1.0, 500.0, 320.0, 240.0, 640, 480)
    with pytest.raises(ValueError, match="principal point"):
        cd.Camera(500.0, 500.0, 900.0, 240.0, 640, 480)
    with pytest.raises(ValueError, match="hfov"):
        cd.Camera.from_hfov(200.0, 640, 480)


def test_bad_points():
    with pytest.raises(ValueError, match="left_points must be an N x 2 array"):
        cd.solve("lm", [1, 2, 3], [[0, 0], [1, 1]], CAMERA, 1.0)
    with pytest.raises(ValueError, match="at least 2 points"):
        cd.symmetry_residual([[1, 40]], [[50, 40], [60, 45]], CAMERA, yaw=0, offset=0, pitch=0,
                             camera_height=1.0)
