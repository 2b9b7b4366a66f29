"""Position-only IK by the reachable pitch range gives the answers of the pitch search
it replaced (kept here as the reference): 3 deg steps outwards from the seed's pitch,
then 0.1 deg steps within reach, then bisection to 1e-4 rad."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from armkit import UnreachableError
from armkit.kinematics import fk, ik, ik_batch, pitch_of
from armkit.kinematics._chain import chain_of
from armkit.model import ArmModel, load_model
from budget import cases

N = cases(full=10_000, quick=2_500)  # OpenManipulator-X targets


def _solve(m: ArmModel, p: np.ndarray, pitch: float) -> np.ndarray | None:
    try:
        return ik(m, p, pitch).q
    except UnreachableError:
        return None


def _within_reach(m: ArmModel, p: np.ndarray) -> bool:
    fam = chain_of(m).family
    assert fam is not None
    reach = sum(math.hypot(*v) for v in fam.links)
    r = math.hypot(p[0], p[1])
    return (
        math.hypot(abs(r) - fam.c1[0], p[2] - fam.c1[1]) <= reach + 1e-9
        or math.hypot(r + fam.c1[0], p[2] - fam.c1[1]) <= reach + 1e-9
    )


def search(m: ArmModel, p: np.ndarray) -> tuple[float, np.ndarray] | None:
    """The pitch search of armkit before the pitch range: (pitch [rad], q) or None."""
    preferred = float(pitch_of(fk(m, m.home)))
    q = _solve(m, p, preferred)
    if q is not None:
        return preferred, q
    for step_deg in (3.0, 0.1) if _within_reach(m, p) else (3.0,):
        step = math.radians(step_deg)
        for k in range(1, int(180 / step_deg) + 1):
            for sign in (1.0, -1.0):
                hit = preferred + sign * k * step
                if _solve(m, p, hit) is not None:
                    miss = preferred + sign * (k - 1) * step
                    while abs(hit - miss) > 1e-4:
                        mid = 0.5 * (miss + hit)
                        hit, miss = (mid, miss) if _solve(m, p, mid) is not None else (hit, mid)
                    q = _solve(m, p, hit)
                    assert q is not None
                    return hit, q
    return None


@pytest.mark.parametrize(("name", "n"), [("openmanipulator_x", N), ("lynx6", 2000)])
def test_same_answers_as_the_search(name: str, n: int) -> None:
    m = load_model(name)
    preferred = float(pitch_of(fk(m, m.home)))
    q = np.random.default_rng(17).uniform(m.lower, m.upper, (n, m.dof))
    P = fk(m, q)[:, :3, 3]
    batch = ik_batch(m, P)
    assert batch.ok.all()
    differ = branch = 0
    for i in range(n):
        ref = search(m, P[i])
        assert ref is not None
        new = ik(m, P[i])
        np.testing.assert_allclose(new.q, batch.q[i], atol=1e-6)
        got = float(pitch_of(fk(m, new.q)))
        gap_new = abs(math.remainder(got - preferred, 2 * math.pi))
        gap_ref = abs(math.remainder(ref[0] - preferred, 2 * math.pi))
        assert gap_new <= gap_ref + 1e-9  # never farther from the seed's pitch
        # the same answer: the search's pitch to its 1e-4 rad bisection, and the same branch
        # (joints within 0.05 rad: at full stretch the elbow moves as the root of the pitch)
        if abs(got - ref[0]) > 1.5e-4:
            differ += 1
            assert gap_new < gap_ref - 1e-4  # a nearer fitting pitch the 3 deg scan skipped
        elif np.abs(new.q - ref[1]).max() > 0.05:
            branch += 1  # exactly at the edge two branches fit; 1e-4 rad inside, one
    print(f"{name}: {differ} nearer pitches, {branch} other branches at the same pitch, of {n}")
    assert differ <= n // 200 and branch <= n // 500, (differ, branch)


@pytest.mark.parametrize("name", ["openmanipulator_x", "lynx6", "so101"])
def test_the_compiled_boundary_search_is_the_lanes_one(name: str) -> None:
    """The compiled search (``_boundaryc.c``, one branch) against ``boundary_pitch`` on
    lanes, and the lanes in floats (the search where the extension is not built), at
    random plane points, both signs of r, and random wanted pitches (issue 29.3); the
    SO-101's chain at its home roll has a tool point beside the plane (lateral)."""
    from armkit.kinematics._boundary_fast import COMPILED
    from armkit.kinematics._closed_scalar import boundary_search
    from armkit.kinematics._lanes import FLOATS
    from armkit.kinematics._near_ik import chain_at
    from armkit.kinematics._pitch_range import boundary_pitch

    m = load_model(name)
    chain = chain_of(m)
    if chain.near is not None:
        chain = chain_at(chain.near, float(m.home[-1]))
    fam = chain.family
    assert COMPILED is not None, "the extension is built by make lint / pip install -e ."
    assert fam is not None and chain.boundary is not None
    rng = np.random.default_rng(29)
    r = rng.uniform(-0.5, 0.5, 3000)
    z = rng.uniform(-0.3, 0.5, 3000)
    want = rng.uniform(-math.pi, math.pi, 3000)
    with np.errstate(invalid="ignore", divide="ignore"):
        gap, pitch = boundary_pitch(chain, fam, r, z, np.abs(r), want)
    found = 0
    for i in range(3000):
        args = (float(r[i]), float(z[i]), abs(float(r[i])), float(want[i]))
        g, p = boundary_search(chain, *args)
        gf, pf = boundary_pitch(chain, fam, *args, FLOATS)
        for g2, p2 in ((g, p), (gf, pf)):
            assert (g2 == gap[i]) or abs(g2 - gap[i]) < 1e-12
            if math.isfinite(g2):
                assert abs(math.remainder(p2 - pitch[i], 2 * math.pi)) < 1e-9
        found += math.isfinite(g)
    assert 300 < found < 2700, found  # both outcomes are exercised
    for i in range(200):  # on the base axis: the gap is the pitch's own distance from want
        args = (0.0, float(z[i]), 0.0, float(want[i]))
        (g, p), (gf, pf) = boundary_search(chain, *args), boundary_pitch(chain, fam, *args, FLOATS)
        assert g == gf or abs(g - gf) < 1e-12
        if math.isfinite(g):
            assert abs(math.remainder(p - pf, 2 * math.pi)) < 1e-9


def test_an_arm_whose_last_link_has_no_length(tmp_path: Path) -> None:
    """The OpenManipulator-X with its tool point on the wrist axis (a fuzzed model file
    found it): the boundary search has no circle; the arm still loads and solves."""
    text = (Path(__file__).parents[2] / "src/armkit/model/arms/openmanipulator_x.toml").read_text()
    path = tmp_path / "omx0.toml"
    path.write_text(text.replace("length_mm = 126.0", "length_mm = 0.0"))
    m = load_model(path)
    assert chain_of(m).boundary is None
    q = np.random.default_rng(5).uniform(m.lower, m.upper, (300, m.dof))
    P = fk(m, q)[:, :3, 3]
    out = ik_batch(m, P)
    for i in range(300):
        try:
            res = ik(m, P[i])
        except UnreachableError:
            assert not out.ok[i]
            continue
        assert np.abs(fk(m, res.q)[:3, 3] - P[i]).max() < 1e-9
