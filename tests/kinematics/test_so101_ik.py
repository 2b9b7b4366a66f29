"""Closed-form IK on the SO-101 and SO-100 (issue 31 item 1), exact on the true chain.

The URDF's rounded right angles leave its axes micro-radians off parallel, and the tool
point sits 7.9 mm beside the wrist_roll axis: the closed form solves the idealised chain
with the roll kept (kinematics/_near.py), Newton's method polishes each solution on the
true chain (kinematics/_near_ik.py). Targets are FK of random joints (fixed seeds) at
least 10 mm from the pan axis: nearer, inside the 7.9 mm the roll swings the tool point,
the pitch as ``pitch_of`` measures it turns with the tool point's direction from the
axis, and a pitch may be reachable only in a narrow window of rolls (docs/arms/so101.md).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import armkit
from armkit import UnreachableError
from armkit.kinematics import closed_form, fk, ik, ik_batch, pitch_of
from armkit.kinematics._chain import chain_of
from armkit.kinematics._closed_scalar import family_ik
from armkit.kinematics._near_ik import chain_at
from budget import cases

N = cases(full=1000, quick=1000)
EXACT_M = 1e-9  # [m] = 1e-6 mm
EXACT_RAD = 1e-9


def targets(name: str, n: int, seed: int) -> tuple[armkit.ArmModel, list[tuple[np.ndarray, float]]]:
    """n reachable targets (tool point [m], its pitch [rad]) of model ``name``."""
    m = armkit.load_model(name)
    rng = np.random.default_rng(seed)
    out = []
    while len(out) < n:
        T = fk(m, rng.uniform(m.lower, m.upper))
        if math.hypot(T[0, 3], T[1, 3]) >= 0.010:
            out.append((T[:3, 3].copy(), float(pitch_of(T))))
    return m, out


@pytest.mark.parametrize("name", ["so101", "so100"])
def test_the_so_arms_get_the_closed_form(name: str) -> None:
    assert closed_form(armkit.load_model(name)) == "base yaw + planar chain"


@pytest.mark.parametrize("name", ["so101", "so100"])
def test_fk_of_ik_is_the_target_with_a_pitch(name: str) -> None:
    m, goals = targets(name, N, 31)
    rng = np.random.default_rng(32)
    for p, pitch in goals:
        seed = rng.uniform(m.lower, m.upper)
        got = ik(m, p, pitch, seed, method="analytic")
        T = fk(m, got.q)
        assert np.linalg.norm(T[:3, 3] - p) <= EXACT_M, (p, pitch, seed)
        assert abs(float(pitch_of(T)) - pitch) <= EXACT_RAD
        assert np.all(got.q >= m.lower) and np.all(got.q <= m.upper)
        for q in got.solutions:  # every solution, not only the best
            assert np.linalg.norm(fk(m, q)[:3, 3] - p) <= EXACT_M


@pytest.mark.parametrize("name", ["so101", "so100"])
def test_fk_of_ik_is_the_target_without_a_pitch(name: str) -> None:
    m, goals = targets(name, N, 33)
    rng = np.random.default_rng(34)
    for p, _ in goals:
        got = ik(m, p, None, rng.uniform(m.lower, m.upper))
        assert np.linalg.norm(fk(m, got.q)[:3, 3] - p) <= EXACT_M, p


def test_the_roll_stays_where_the_seed_has_it() -> None:
    """The roll moves only where the idealised closed form has no solution at the seed's."""
    m, goals = targets("so101", 200, 35)
    near = chain_of(m).near
    assert near is not None and near.deviation < 1e-5  # the rounding, a few micrometres
    rng = np.random.default_rng(36)
    kept = 0
    for p, pitch in goals:
        seed = rng.uniform(m.lower, m.upper)
        q = ik(m, p, pitch, seed).q
        kept += q[-1] == seed[-1]
        if q[-1] != seed[-1]:
            with pytest.raises(UnreachableError):
                family_ik(chain_at(near, seed[-1]), tuple(p), pitch, tuple(seed[:-1]))
    assert kept >= 150


def test_the_batch_solves_as_ik_does() -> None:
    m, goals = targets("so101", 300, 37)
    P = np.array([p for p, _ in goals])
    pitches = np.array([pitch for _, pitch in goals])
    seed = np.random.default_rng(38).uniform(m.lower, m.upper, (len(P), m.dof))
    got = ik_batch(m, P, pitches, seed)
    assert got.method == "analytic" and got.ok.all()
    for k in range(len(P)):
        T = fk(m, got.q[k])
        assert np.linalg.norm(T[:3, 3] - P[k]) <= EXACT_M
        assert abs(float(pitch_of(T)) - pitches[k]) <= EXACT_RAD
        np.testing.assert_allclose(got.q[k], ik(m, P[k], pitches[k], seed[k]).q, atol=1e-12)


@pytest.mark.parametrize(
    ("p", "pitch", "reason", "words"),
    [
        ((0.6, 0.0, 0.2), 0.0, "too_far", "too far away"),
        ((0.05, 0.0, 0.2), 1.0, "joint_limit", "shoulder_lift would be"),
        ((0.02, 0.0, 0.3), 1.5, "joint_limit", "elbow_flex would be"),
        ((0.2, 0.1, 0.1), -1.5, "joint_limit", "wrist_flex would be"),
        ((0.0, 0.0, 0.1), -1.5, "too_close", "too close to the base"),
    ],
)
def test_refusals_say_why(
    p: tuple[float, float, float], pitch: float, reason: str, words: str
) -> None:
    m = armkit.load_model("so101")
    with pytest.raises(UnreachableError) as caught:
        ik(m, p, pitch)
    assert caught.value.reason == reason
    assert words in str(caught.value) and "so101 cannot reach" in str(caught.value)
    got = ik_batch(m, np.array([p]), pitch)
    assert not got.ok[0] and got.reason[0] == reason
