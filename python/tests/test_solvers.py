"""The solvers by name on hand-projected junction points of a known corridor."""

import numpy as np
import pytest

import corridor_depth as cd
import corridor_by_hand as hand

CAMERA = cd.Camera(hand.FX, hand.FY, hand.CX, hand.CY, hand.WIDTH_PX, hand.HEIGHT_PX)


def test_the_hand_projection_is_a_corridor():
    """Both junctions pass through the vanishing point and lie inside the image."""
    for points in (hand.LEFT, hand.RIGHT):
        direction = points[-1] - points[0]
        to_vp = hand.VANISHING_POINT - points[0]
        assert abs(direction[0] * to_vp[1] - direction[1] * to_vp[0]) < 1e-6 * np.linalg.norm(
            direction) * np.linalg.norm(to_vp)
        assert (points[:, 0] > 0).all() and (points[:, 0] < hand.WIDTH_PX).all()
        assert (points[:, 1] > hand.CY - 60).all() and (points[:, 1] < hand.HEIGHT_PX).all()


@pytest.mark.parametrize("name,angle_tol,length_tol", [
    ("closed_form", 1e-6, 1e-5), ("lm", 1e-5, 1e-4), ("joint", 1e-5, 1e-4),
    ("closed_form+lm", 1e-6, 1e-5), ("grid", 2e-3, 1e-2)])
def test_solver_recovers_the_corridor(name, angle_tol, length_tol):
    geometry, summary = cd.solve(name, hand.LEFT, hand.RIGHT, CAMERA, hand.H)
    assert summary.solver_name == name
    assert summary.estimate.width == geometry.width
    assert geometry.yaw == pytest.approx(hand.YAW, abs=angle_tol)
    assert geometry.pitch == pytest.approx(hand.PITCH, abs=angle_tol)
    assert geometry.offset == pytest.approx(hand.OFFSET, abs=length_tol)
    assert geometry.width == pytest.approx(hand.WIDTH, abs=length_tol)
    assert geometry.left_distance == pytest.approx(hand.D_LEFT, abs=length_tol)
    assert geometry.camera_height == hand.H


def test_height_scales_the_corridor_and_initial_is_taken():
    geometry, _ = cd.solve("closed_form", hand.LEFT, hand.RIGHT, CAMERA, 2 * hand.H)
    assert geometry.width == pytest.approx(2 * hand.WIDTH, abs=1e-5)
    assert geometry.yaw == pytest.approx(hand.YAW, abs=1e-6)
    start = cd.Geometry(yaw=0.09, pitch=0.07, offset=0.25, width=2.3, camera_height=hand.H)
    geometry, summary = cd.solve("lm", hand.LEFT, hand.RIGHT, CAMERA, hand.H, initial=start,
                                 loss="none")
    assert geometry.width == pytest.approx(hand.WIDTH, abs=1e-4)
    assert summary.converged


def test_unknown_solver_lists_the_valid_names():
    with pytest.raises(ValueError, match="valid: grid, closed_form, lm, joint"):
        cd.solve("newton", hand.LEFT, hand.RIGHT, CAMERA, hand.H)
