"""The two cost functors: zero at the true parameters, hand-computed values away from them."""

import math

import numpy as np
import pytest

import corridor_depth as cd
import corridor_by_hand as hand

CAMERA = cd.Camera(hand.FX, hand.FY, hand.CX, hand.CY, hand.WIDTH_PX, hand.HEIGHT_PX,
                   camera_height=hand.H)
N = len(hand.ALONG)


def symmetry(**change):
    x = dict(yaw=hand.YAW, offset=hand.OFFSET, pitch=hand.PITCH)
    x.update(change)
    return cd.symmetry_residual(hand.LEFT, hand.RIGHT, CAMERA, **x)


def width(**change):
    x = dict(pitch=hand.PITCH, width=hand.WIDTH, yaw=hand.YAW, offset=hand.OFFSET)
    x.update(change)
    return cd.width_residual(hand.LEFT, hand.RIGHT, CAMERA, **x)


def test_symmetry_residual_zero_at_truth_nonzero_away():
    r = symmetry()
    assert r.shape == (2 * N,)
    assert np.abs(r).max() < 1e-6
    assert np.abs(symmetry(yaw=hand.YAW + 0.05)).max() > 1.0
    assert np.abs(symmetry(offset=hand.OFFSET + 0.2)).max() > 1.0


def test_width_residual_zero_at_truth():
    r = width()
    assert r.shape == (2 * N,)
    assert np.abs(r).max() < 1e-9
    assert np.abs(width(pitch=hand.PITCH + 0.03)).max() > 1.0


def test_width_residual_away_by_hand():
    """At the true angles and offset, a width off by delta puts each point delta / 2 off its
    wall: r = (fx / z) * (X_W - wall X) = +fx delta / (2 z) on the left, -fx delta / (2 z) on
    the right, z the point's camera-frame depth."""
    delta = 0.3
    expected = np.concatenate([hand.FX * delta / (2 * hand.LEFT_C[:, 2]),
                               -hand.FX * delta / (2 * hand.RIGHT_C[:, 2])])
    np.testing.assert_allclose(width(width=hand.WIDTH + delta), expected, rtol=1e-9)
    # Huber (scale a): a residual beyond a becomes sign(r) sqrt(2 a |r| - a^2).
    a = 2.0
    huber = np.where(np.abs(expected) <= a, expected,
                     np.sign(expected) * np.sqrt(2 * a * np.abs(expected) - a * a))
    r = cd.width_residual(hand.LEFT, hand.RIGHT, CAMERA, pitch=hand.PITCH,
                          width=hand.WIDTH + delta, yaw=hand.YAW, offset=hand.OFFSET,
                          loss="huber", loss_scale=a)
    np.testing.assert_allclose(r, huber, rtol=1e-9)
    assert (np.abs(expected) > a).any()


def test_camera_height_given_or_taken_from_the_camera():
    doubled = cd.width_residual(hand.LEFT, hand.RIGHT, CAMERA, pitch=hand.PITCH,
                                width=2 * hand.WIDTH, yaw=hand.YAW, offset=2 * hand.OFFSET,
                                camera_height=2 * hand.H)
    assert np.abs(doubled).max() < 1e-9  # The same image of a corridor twice as large.


def test_undefined_parameters_raise():
    with pytest.raises(ValueError, match="undefined"):
        width(pitch=-math.pi / 2 + 0.01)
