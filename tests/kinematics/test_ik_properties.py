"""Property tests: fk(ik(p)) == p on every arm, through every entry point; ik(fk(q)) finds q."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from armkit import UnreachableError
from armkit.kinematics import _closed, fk, ik, ik_batch, pitch_of
from armkit.kinematics._chain import chain_of
from armkit.kinematics._pitch_range import free_batch
from armkit.model import load_model

ARMS = ["owi535", "openmanipulator_x", "lynx6", "planar2"]
N = 10_000


def reachable(name: str, n: int, seed: int) -> tuple[np.ndarray, np.ndarray, np.ndarray | None]:
    """Random joint vectors inside the limits, their tool points and pitches."""
    m = load_model(name)
    q = np.random.default_rng(seed).uniform(m.lower, m.upper, (n, m.dof))
    T = fk(m, q)
    pitch = None if name == "planar2" else np.asarray(pitch_of(T))
    return q, T[:, :3, 3], pitch


@pytest.mark.parametrize("name", ARMS)
def test_single_round_trip_10000(name: str) -> None:
    m = load_model(name)
    q, P, pitch = reachable(name, N, 1)
    worst = 0.0
    for i in range(N):
        res = ik(m, P[i], None if pitch is None else pitch[i], q_seed=q[i])
        assert m.within_limits(res.solutions).all()
        worst = max(worst, float(np.abs(fk(m, res.solutions)[:, :3, 3] - P[i]).max()))
        assert np.abs(res.solutions - q[i]).max(axis=1).min() < 1e-6  # q itself is found
    assert worst < 1e-9


@pytest.mark.parametrize("name", ARMS)
def test_batch_round_trip_10000(name: str) -> None:
    m = load_model(name)
    q, P, pitch = reachable(name, N, 2)
    res = ik_batch(m, P, pitch, q_seed=q)
    assert res.ok.all() and (res.reason == "").all()
    assert m.within_limits(res.q).all()
    assert np.abs(fk(m, res.q)[:, :3, 3] - P).max() < 1e-9
    assert np.abs(res.q - q).max() < 1e-6  # seeded with q, the nearest branch is q


@pytest.mark.parametrize(
    "name", [a for a in ARMS if a != "planar2"]
)  # planar2: pitch follows position
def test_pitch_is_met(name: str) -> None:
    m = load_model(name)
    _, P, pitch = reachable(name, 500, 3)
    assert pitch is not None
    res = ik_batch(m, P, pitch)
    got = np.asarray(pitch_of(fk(m, res.q[res.ok])))
    assert np.abs(np.remainder(got - pitch[res.ok] + math.pi, 2 * math.pi) - math.pi).max() < 1e-9


def reference(m, p: np.ndarray, pitch: float | None) -> np.ndarray:  # type: ignore[no-untyped-def]
    """Every solution by the vectorised closed form (the reference), best first."""
    chain = chain_of(m)
    fam = chain.family
    seed = chain.home_a[None, :]
    if pitch is None and len(fam.planar) == 3:
        q, ok = free_batch(chain, fam, p[None, :], seed)
        return q[ok]
    c = _closed.solve(chain, fam, p[None, :], None if pitch is None else np.array([pitch]), seed)
    valid = c.q[0][c.valid[0]]
    order = np.argsort(((valid - seed) ** 2).sum(axis=1), kind="stable")
    unique: list[np.ndarray] = []
    for q in valid[order]:
        if all(np.abs(q - u).max() > 1e-9 for u in unique):
            unique.append(q)
    return np.array(unique)


@pytest.mark.parametrize("name", ARMS)
@pytest.mark.parametrize("free", [False, True])
def test_fast_path_agrees_with_reference(name: str, free: bool) -> None:
    """The scalar fast path and the vectorised reference return the same solutions."""
    m = load_model(name)
    _, P, pitch = reachable(name, 300, 4)
    for i in range(len(P)):
        pt = None if pitch is None or free else float(pitch[i])
        if free and name == "owi535":
            pt = 0.0  # the OWI's default pitch: level
        try:
            fast = ik(m, tuple(P[i].tolist()), pt).solutions
        except UnreachableError:
            fast = np.zeros((0, m.dof))
        ref = reference(m, P[i], pt).reshape(-1, m.dof)
        if free and name not in ("owi535", "planar2"):
            fast = fast[:1]  # the reference returns the best only
        assert fast.shape == ref.shape and np.allclose(fast, ref, atol=1e-9)


@pytest.mark.parametrize("name", ARMS)
def test_position_only(name: str) -> None:
    """Without a pitch the OWI keeps its gripper level (000); the others choose one."""
    m = load_model(name)
    _, P, _ = reachable(name, 200, 5)
    res = ik_batch(m, P)
    if name == "owi535":
        assert not res.ok.all()  # most random points are not reachable with a level gripper
        level = np.asarray(pitch_of(fk(m, res.q[res.ok])))
        assert np.abs(level).max() < 1e-9
    else:
        assert res.ok.all()
    assert np.abs(fk(m, res.q[res.ok])[:, :3, 3] - P[res.ok]).max() < 1e-9
    for i in np.flatnonzero(res.ok)[:20]:
        single = ik(m, P[i])
        assert np.allclose(fk(m, single.q)[:3, 3], P[i], atol=1e-9)


@settings(max_examples=200, deadline=None, derandomize=True)
@given(
    st.sampled_from(ARMS),
    st.floats(-0.6, 0.6),
    st.floats(-0.6, 0.6),
    st.floats(-0.3, 1.1),
    st.floats(-math.pi, math.pi),
)
def test_any_answer_is_exact_and_inside_limits(
    name: str, x: float, y: float, z: float, p: float
) -> None:
    m = load_model(name)
    if name == "planar2":
        y, p = 0.0, None  # type: ignore[assignment]
    try:
        res = ik(m, (x, y, z), p)
    except UnreachableError as exc:
        assert exc.reason in {"too_far", "too_close", "joint_limit", "pitch", "off_plane"}
        return
    assert m.within_limits(res.solutions).all()
    assert np.abs(fk(m, res.solutions)[:, :3, 3] - [x, y, z]).max() < 1e-9
    assert res.position_error < 1e-9 and res.angle_error < 1e-9


def test_batch_and_single_agree_on_failures() -> None:
    m = load_model("openmanipulator_x")
    P = np.array([[2.0, 0, 0], [0.2, 0, 0.05], [0.0, 0.0, 0.077]])
    res = ik_batch(m, P, np.full(3, -math.pi / 2))
    assert res.ok.tolist() == [False, True, False]
    assert res.reason[0] == "too_far"
    assert np.isnan(res.q[0]).all()


@pytest.mark.parametrize("name", ["openmanipulator_x", "lynx6"])
def test_position_only_batch_agrees_with_single(name: str) -> None:
    """The vectorised pitch search picks the same pitch, so the same joints, as ik()."""
    m = load_model(name)
    _, P, _ = reachable(name, 300, 6)
    batch = ik_batch(m, P)
    assert batch.ok.all()
    for i in range(len(P)):
        assert np.abs(ik(m, P[i]).q - batch.q[i]).max() < 1e-6
