"""The source documents' own formulas, typos fixed, reproduced against armkit's FK and IK."""

from __future__ import annotations

import math

import numpy as np
import pytest

from armkit.kinematics import fk, ik, pitch_of
from armkit.model import load_model

RNG = np.random.default_rng(20261121)
D = math.radians


# --- 000: the OWI-535 (calcIK and getCoord, seed frame: x right, y forward) ---------------


def owi_getcoord(base: float, shoulder: float, elbow: float) -> tuple[float, float, float]:
    """000's getCoord in degrees -> seed (x, y, z) mm."""
    U, L, G, B = 90.0, 110.0, 110.0, 70.0
    se = D(180 - (shoulder + elbow))
    rdist = U * math.sin(D(shoulder)) + L * math.sin(se) + G
    z = B + U * math.cos(D(shoulder)) - L * math.cos(se)
    return rdist * math.sin(D(base)), rdist * math.cos(D(base)), z


def owi_calcik(x: float, y: float, z: float) -> tuple[float, float, float, float]:
    """000's calcIK (seed frame, mm) -> base, shoulder, elbow, wrist in degrees (unrounded)."""
    U, L, G, B = 90.0, 110.0, 110.0, 70.0
    base = math.degrees(math.atan2(x, y))
    rdist = math.hypot(x, y)
    wz, wy = z - B, rdist - G
    sw2 = wz * wz + wy * wy
    sw1 = math.atan2(wz, wy)
    sw2a = math.acos((U * U + sw2 - L * L) / (2 * U * math.sqrt(sw2)))
    shoulder = 90.0 - math.degrees(sw1 + sw2a)
    elbow = 180.0 - math.degrees(math.acos((U * U + L * L - sw2) / (2 * U * L)))
    return base, shoulder, elbow, 90.0 - (shoulder + elbow)


def test_owi_getcoord_matches_fk() -> None:
    m = load_model("owi535")
    for _ in range(200):
        b, s, e = RNG.uniform(-120, 120), RNG.uniform(-80, 100), RNG.uniform(-140, 140)
        T = fk(m, np.radians([b, s, e, 90 - s - e]))
        xs, ys, z = owi_getcoord(b, s, e)
        if math.hypot(xs, ys) < 1e-3:
            continue
        assert np.allclose(T[:3, 3] * 1000, [ys, -xs, z], atol=1e-9)  # seed (x, y) = our (-y, x)
        # gripper horizontal: pointing away from the base (0) or, reaching back past the base
        # axis, towards it (180); pitch is measured from the outward horizontal
        assert min(abs(float(pitch_of(T))), math.pi - abs(float(pitch_of(T)))) < 1e-9


def test_owi_calcik_is_one_of_armkits_solutions() -> None:
    m = load_model("owi535")
    for x, y, z in [(120, 180, 60), (-90, 150, 100), (0, 250, 20), (60, 200, 150)]:
        want = np.radians(owi_calcik(x, y, z))
        target = np.array([y, -x, z]) / 1000.0
        assert np.allclose(fk(m, want)[:3, 3], target, atol=1e-12)
        got = ik(m, target)  # no pitch: the OWI keeps its gripper horizontal, as calcIK
        assert np.min(np.abs(got.solutions - want).max(axis=1)) < 1e-9


# --- 001: the OpenManipulator-X (DH table and the r-z inverse kinematics) -----------------
# 001 rounds ROBOTIS's geometry (0.077 m, a 0.130 m link at 10.62 deg); the model uses the
# exact numbers of ROBOTIS's URDF, so the seed's formulas are checked with those.
D1 = 0.0765  # joint 2 above the base origin [m]
A2 = math.hypot(0.024, 0.128)  # 0.1302306 m
OFF = D(90) - math.atan2(0.024, 0.128)  # 90 - 10.6197 deg


def robotis_fk(q: np.ndarray) -> np.ndarray:
    """The tool point [m] by ROBOTIS's URDF (open_manipulator_description/urdf/
    open_manipulator.urdf.xacro): joint origins and axes, in ROBOTIS's base frame."""

    def trans(x: float, y: float, z: float) -> np.ndarray:
        T = np.eye(4)
        T[:3, 3] = x, y, z
        return T

    def rot(axis: int, a: float) -> np.ndarray:
        T, c, s = np.eye(4), math.cos(a), math.sin(a)
        i, j = [(1, 2), (2, 0), (0, 1)][axis]
        T[i, i], T[i, j], T[j, i], T[j, j] = c, -s, s, c
        return T

    T = trans(0.012, 0.0, 0.017) @ rot(2, q[0]) @ trans(0.0, 0.0, 0.0595) @ rot(1, q[1])
    T = T @ trans(0.024, 0.0, 0.128) @ rot(1, q[2]) @ trans(0.124, 0.0, 0.0) @ rot(1, q[3])
    return T @ trans(0.126, 0.0, 0.0)


def test_omx_fk_is_robotis_urdf_to_a_nanometre() -> None:
    """armkit's origin is on the waist axis: ROBOTIS's x = armkit's x + 0.012 m."""
    m = load_model("openmanipulator_x")
    q = RNG.uniform(m.lower, m.upper, (300, 4))
    for qi in q:
        ref = robotis_fk(qi)
        T = fk(m, qi)
        assert np.abs(T[:3, 3] + [0.012, 0.0, 0.0] - ref[:3, 3]).max() < 1e-9
        assert np.abs(T[:3, 0] - ref[:3, 0]).max() < 1e-9  # the approach axis
    home = fk(m, np.zeros(4))[:3, 3]  # the standard pose: 0.024 + 0.124 + 0.126 forward
    assert np.allclose(home, [0.274, 0.0, 0.0765 + 0.128], atol=1e-12)


def mdh(alpha: float, a: float, d: float, theta: float) -> np.ndarray:
    ca, sa, ct, st = math.cos(alpha), math.sin(alpha), math.cos(theta), math.sin(theta)
    return np.array(
        [
            [ct, -st, 0, a],
            [st * ca, ct * ca, -sa, -sa * d],
            [st * sa, ct * sa, ca, ca * d],
            [0, 0, 0, 1],
        ]
    )


def omx_seed_fk(t1: float, t2: float, t3: float, t4: float) -> np.ndarray:
    """001's DH table (alpha_{i-1}, a_{i-1}, d_i, theta_i), radians, metres."""
    off = OFF
    T = mdh(0, 0, D1, t1) @ mdh(D(90), 0, 0, t2 + off) @ mdh(0, A2, 0, t3 - off)
    return T @ mdh(0, 0.124, 0, t4) @ mdh(0, 0.126, 0, 0)


def test_omx_dh_table_matches_fk() -> None:
    """001's table turns joints 2-4 about -y (alpha = +90); ROBOTIS angles turn about +y."""
    m = load_model("openmanipulator_x")
    q = RNG.uniform(m.lower, m.upper, (300, 4))
    for qi in q:
        seed_T = omx_seed_fk(qi[0], -qi[1], -qi[2], -qi[3])
        assert np.allclose(fk(m, qi)[:3, 3], seed_T[:3, 3], atol=1e-12)


def omx_seed_ik(x: float, y: float, z: float, phi: float, elbow: float) -> np.ndarray:
    """001 section 5.2 with its typos fixed: acos((r2^2 + z2^2 - (a2^2 + a3^2)) / (2 a2 a3)) and
    sin(theta2) = (z2 (a2 + a3 c3) - r2 a3 s3) / (r2^2 + z2^2) (the text prints '+'), then the
    servo conversion (also fixed) to ROBOTIS joint angles."""
    a2, a3, a4 = A2, 0.124, 0.126
    t1 = math.atan2(y, x)
    r3, z3 = math.hypot(x, y), z - D1
    r2, z2 = r3 - a4 * math.cos(phi), z3 - a4 * math.sin(phi)
    t3 = elbow * math.acos((r2 * r2 + z2 * z2 - (a2 * a2 + a3 * a3)) / (2 * a2 * a3))
    k1, k2 = a2 + a3 * math.cos(t3), a3 * math.sin(t3)
    c2 = (r2 * k1 + z2 * k2) / (r2 * r2 + z2 * z2)
    s2 = (z2 * k1 - r2 * k2) / (r2 * r2 + z2 * z2)
    t2 = math.atan2(s2, c2)
    t4 = phi - t2 - t3
    off = OFF
    return np.array([t1, off - t2, -t3 - off, -t4])


def test_omx_seed_ik_matches_armkit() -> None:
    m = load_model("openmanipulator_x")
    for x, y, z, phi in [
        (0.20, 0.0, 0.05, -90),
        (0.15, 0.10, 0.10, -45),
        (0.25, -0.05, 0.15, 0),
        (0.18, 0.0, 0.2, 20),
    ]:
        got = ik(m, (x, y, z), D(phi))
        for branch in (-1.0, 1.0):
            q = omx_seed_ik(x, y, z, D(phi), branch)
            assert np.allclose(fk(m, q)[:3, 3], [x, y, z], atol=1e-12)
            if m.within_limits(q):
                assert np.min(np.abs(got.solutions - q).max(axis=1)) < 1e-9


# --- 002: the Lynx6 (SolveXYZ / SolveRZ, inches, seed frame x right, y forward) ------------


def lynx_solve(x: float, y: float, z: float, grip_angle: float, grip_len: float) -> np.ndarray:
    """002's SolveXYZ + SolveRZ with h = sqrt(z'^2 + r'^2) / 2 (the note prints z'^2 * r'^2)."""
    base = math.atan2(y, x)
    r = math.hypot(x, y)
    rp = r - math.sin(grip_angle) * grip_len
    zp = z - 3.0 + math.cos(grip_angle) * grip_len
    h = math.sqrt(zp * zp + rp * rp) / 2
    elbow = math.asin(h / 4.75) * 2
    shoulder = math.atan2(zp, rp) + (math.pi - elbow) / 2
    wrist = math.pi + grip_angle - shoulder - elbow
    return np.array([base, shoulder, elbow, wrist, math.pi / 2])


def test_lynx_solve_matches_fk_and_ik() -> None:
    """002's grip angle is measured from straight down: armkit pitch = grip angle - 90 deg."""
    for xs, ys, z, g, grip_len in [
        (0, 7, 2, 45, 5.9),
        (3, 6, 1, 30, 5.5),
        (-2, 8, 4, 90, 5.2),
        (1, 5, 0.5, 10, 5.9),
    ]:
        m = load_model("lynx6").with_tool_length(grip_len * 0.0254)
        q = lynx_solve(xs, ys, z, D(g), grip_len)
        target = np.array([ys, -xs, z]) * 0.0254
        T = fk(m, q)
        assert np.allclose(T[:3, 3], target, atol=1e-12)
        assert math.isclose(float(pitch_of(T)), D(g - 90), abs_tol=1e-12)
        got = ik(m, target, D(g - 90))
        assert np.min(np.abs(got.solutions - q).max(axis=1)) < 1e-9


def test_lynx_grip_width_moves_the_grip_point() -> None:
    m = load_model("lynx6")
    assert math.isclose(m.tool_length, 5.9 * 0.0254)
    open_ = m.with_grip_width(2.0 * 0.0254)
    assert math.isclose(open_.tool_length, 5.2 * 0.0254, rel_tol=1e-4)
    with pytest.raises(ValueError, match="grip width"):
        m.with_grip_width(0.06)


# --- 003: the two-link arm (law of cosines) -----------------------------------------------


def test_planar2_law_of_cosines() -> None:
    m = load_model("planar2")
    L1 = L2 = 500.0
    for x, y in [(250, 250), (600, 300), (100, 900), (-300, 500)]:
        t2 = math.acos((x * x + y * y - L1 * L1 - L2 * L2) / (2 * L1 * L2))
        t1 = math.asin(L2 * math.sin(t2) / math.hypot(x, y)) + math.atan2(x, y)
        target = np.array([x, 0.0, y]) / 1000.0  # 003's (x, y) is our (x, z)
        assert np.allclose(fk(m, [t1, t2])[:3, 3], target, atol=1e-12)
        got = ik(m, target)
        assert np.min(np.abs(got.solutions - [t1, t2]).max(axis=1)) < 1e-9
        assert len(got.solutions) == 2  # both elbow branches
