"""Full-pose targets through the public batch entry point (numeric)."""

from __future__ import annotations

import numpy as np
import pytest

from armkit import fk, ik_batch, load_model


def test_puma_full_pose_batch() -> None:
    m = load_model("puma560")
    q = np.random.default_rng(11).uniform(m.lower, m.upper, (100, 6))
    T = fk(m, q)
    res = ik_batch(m, T[:, :3, 3], orientations=T[:, :3, :3], method="lm")
    assert res.method == "lm" and res.ok.all() and m.within_limits(res.q).all()
    got = fk(m, res.q)
    assert np.linalg.norm(got[:, :3, 3] - T[:, :3, 3], axis=1).max() < 1e-5  # tol_mm = 0.01
    assert np.abs(got[:, :3, :3] - T[:, :3, :3]).max() < 1e-3


def test_pitches_and_orientations_are_exclusive() -> None:
    m = load_model("puma560")
    with pytest.raises(ValueError, match="not both"):
        ik_batch(m, np.zeros((2, 3)), np.zeros(2), orientations=np.tile(np.eye(3), (2, 1, 1)))
