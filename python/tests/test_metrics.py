"""depth_metrics on hand-computed arrays."""

import math

import numpy as np
import pytest

import corridor_depth as cd

# Truth 1, 2 and 4 m (and one pixel without, 0); predictions 1, 2.2, none (NaN) and 3.
PRED = np.array([[1.0, 2.2], [np.nan, 3.0]], np.float32)
TRUTH = np.array([[1.0, 2.0], [4.0, 0.0]], np.float32)


def test_hand_computed_metrics():
    m = cd.depth_metrics(PRED, TRUTH)
    # Evaluated: (1, 1) and (2.2, 2); the 4 m pixel has no prediction, the 3 m one no truth.
    assert (m.num_gt, m.num_evaluated) == (3, 2)
    assert m.coverage == pytest.approx(2 / 3)
    assert m.abs_rel == pytest.approx((0 + 0.2 / 2) / 2, rel=1e-6)
    assert m.sq_rel == pytest.approx((0 + 0.04 / 2) / 2, rel=1e-5)
    assert m.rmse == pytest.approx(math.sqrt(0.04 / 2), rel=1e-6)
    assert m.rmse_log == pytest.approx(math.sqrt(math.log(1.1) ** 2 / 2), rel=1e-5)
    assert m.rmse_log10 == pytest.approx(math.sqrt(math.log10(1.1) ** 2 / 2), rel=1e-5)
    assert m.log10 == pytest.approx(math.log10(1.1) / 2, rel=1e-5)
    assert (m.delta1, m.delta2, m.delta3) == (1.0, 1.0, 1.0)
    assert m.as_dict()["abs_rel"] == m.abs_rel


def test_cap_zero_prediction_and_millimetres():
    capped = cd.depth_metrics(PRED, TRUTH, max_depth=3.0)  # The 4 m pixel is left out.
    assert (capped.num_gt, capped.num_evaluated, capped.coverage) == (2, 2, 1.0)
    zero = np.nan_to_num(PRED, nan=0.0)  # 0 is "no estimate" too.
    assert cd.depth_metrics(zero, TRUTH).abs_rel == cd.depth_metrics(PRED, TRUTH).abs_rel
    mm = np.array([[1000, 2200], [0, 3000]], np.uint16)
    truth_mm = np.array([[1000, 2000], [4000, 0]], np.uint16)
    assert cd.depth_metrics(mm, truth_mm).abs_rel == pytest.approx(0.05, rel=1e-6)


def test_a_factor_of_two_everywhere():
    truth = np.full((3, 3), 2.0, np.float32)
    m = cd.depth_metrics(truth * 2, truth)
    assert m.abs_rel == pytest.approx(1.0)
    assert m.rmse == pytest.approx(2.0)
    assert (m.delta1, m.delta2, m.delta3) == (0.0, 0.0, 0.0)  # 2 > 1.25^3 = 1.95


def test_sizes_must_agree():
    with pytest.raises(ValueError, match="differ in size"):
        cd.depth_metrics(np.ones((2, 2), np.float32), np.ones((3, 3), np.float32))
