"""Batch LM: every solved target verified by fk, limits held, failures marked."""

from __future__ import annotations

import numpy as np
import pytest
from numeric_cases import ARMS, TOL_ANG, TOL_POS, joint_vectors, masks_for

from armkit.kinematics import fk, ik_batch, pitch_of
from armkit.kinematics._chain import chain_of
from armkit.kinematics._numeric import solve_many
from armkit.model import load_model

CASES = [(arm, mask) for arm in ARMS for mask in masks_for(load_model(arm))]


@pytest.mark.parametrize(("arm", "mask"), CASES)
def test_batch_reaches_reachable_targets(arm: str, mask: str) -> None:
    model = load_model(arm)
    T = fk(model, joint_vectors(model, 40, seed=5))
    pitches = pitch_of(T) if mask == "position+pitch" else None
    R = T[:, :3, :3] if mask == "pose" else None
    seeds = np.repeat(model.home[None], len(T), axis=0)  # solve_many: no default pitch applied
    out = solve_many(chain_of(model), T[:, :3, 3], pitches, R, seeds, TOL_POS, TOL_ANG)
    assert out.method == "lm"
    assert out.ok.all(), out.reason[~out.ok]
    assert model.within_limits(out.q, slack=0.0).all()
    Tq = fk(model, out.q)
    assert np.linalg.norm(Tq[:, :3, 3] - T[:, :3, 3], axis=1).max() <= TOL_POS * 1.0001
    if pitches is not None:
        d = np.remainder(pitch_of(Tq) - pitches + np.pi, 2 * np.pi) - np.pi
        assert np.abs(d).max() <= TOL_ANG * 1.0001


def test_batch_marks_unreachable_targets_and_accepts_per_target_seeds() -> None:
    model = load_model("openmanipulator_x")
    T = fk(model, joint_vectors(model, 30, seed=6))
    P = T[:, :3, 3].copy()
    P[3] = [3.0, 0.0, 0.0]
    seeds = np.repeat(model.home[None], 30, axis=0)
    out = ik_batch(model, P, None, seeds, method="lm", tol_m=TOL_POS, tol_rad=TOL_ANG)
    assert not out.ok[3] and out.reason[3] == "too_far" and np.isnan(out.q[3]).all()
    assert out.ok[np.arange(30) != 3].all()
    assert (out.reason[out.ok] == "").all()
