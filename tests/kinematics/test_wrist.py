"""The spherical-wrist closed form (issue 29.1): every branch by FK, the branch set complete,
the scalar solver pinned to the vectorised one, recognised whatever the frames."""

from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np
import pytest

from armkit import InputError, UnreachableError, fk, ik, ik_batch, load_model
from armkit.interchange import urdf_of
from armkit.kinematics import closed_form
from armkit.kinematics._chain import chain_of
from armkit.kinematics._wrist_batch import solve_wrist_batch
from armkit.model import ArmModel

PUMA = Path(__file__).parents[2] / "src/armkit/model/arms/puma560.toml"


def puma_variant(tmp_path: Path, limits: str | None = None, d5: float = 0.0) -> ArmModel:
    """The PUMA 560 file with every limit replaced by ``limits`` (TOML), or a wrist offset d5 [mm]."""
    text = PUMA.read_text()
    if limits is not None:
        text = re.sub(r"limits_deg = \[[^\]]*\]", f"limits_deg = {limits}", text)
    text = text.replace("alpha_deg = -90.0, d_mm = 0.0 }", f"alpha_deg = -90.0, d_mm = {d5} }}")
    path = tmp_path / "puma.toml"
    path.write_text(text)
    return load_model(path)


def targets(m: ArmModel, n: int, seed: int) -> tuple[np.ndarray, np.ndarray]:
    q = np.random.default_rng(seed).uniform(m.lower, m.upper, (n, m.dof))
    return q, fk(m, q)


def test_every_branch_reaches_the_pose_and_the_target_s_own_q_is_among_them() -> None:
    m = load_model("puma560")
    q, T = targets(m, 2000, 1)
    for i in range(len(q)):
        res = ik(m, T[i, :3, 3], orientation=T[i, :3, :3], q_seed=q[i])
        assert res.method == "analytic" and m.within_limits(res.solutions).all()
        assert np.abs(fk(m, res.solutions) - T[i]).max() < 1e-9
        assert np.abs(res.solutions - q[i]).max(axis=1).min() < 1e-7  # the set is complete
        assert np.abs(res.q - q[i]).max() < 1e-7  # and the seed's own is the best


def test_without_limits_a_general_pose_has_all_eight_branches(tmp_path: Path) -> None:
    m = puma_variant(tmp_path, "[-180.0, 180.0]")
    assert closed_form(m) == "spherical wrist"
    q, T = targets(m, 300, 2)
    for i in range(len(q)):
        res = ik(m, T[i, :3, 3], orientation=T[i, :3, :3])
        assert len(res.solutions) == 8
        assert np.abs(fk(m, res.solutions) - T[i]).max() < 1e-9


def test_the_scalar_solver_is_pinned_to_the_batch() -> None:
    m = load_model("puma560")
    q, T = targets(m, 3000, 3)
    seeds = np.random.default_rng(4).uniform(m.lower, m.upper, (3000, 6))
    out = ik_batch(m, T[:, :3, 3], orientations=T[:, :3, :3], q_seed=seeds)
    assert out.method == "analytic" and out.ok.all()
    c = chain_of(m)
    for i in range(len(q)):
        found = c.wrist_solve(
            *T[i, :3, 3].tolist(), tuple(T[i, :3, :3].ravel()), tuple(seeds[i]), None
        )
        assert np.abs(np.array(min(found)[1]) - out.q[i]).max() < 1e-9


def test_a_singular_wrist_keeps_the_seed_s_roll_and_still_reaches() -> None:
    m = load_model("puma560")
    qs = np.radians([20.0, 40.0, -100.0, 35.0, 0.0, -50.0])  # q5 = 0: axes 4 and 6 in line
    T = fk(m, qs)
    seed = qs + np.radians([0, 0, 0, 10.0, 0, 0])
    res = ik(m, T[:3, 3], orientation=T[:3, :3], q_seed=seed)
    assert np.abs(fk(m, res.solutions) - T).max() < 1e-9
    assert abs(res.q[3] - seed[3]) < 1e-9
    q, ok = solve_wrist_batch(
        chain_of(m).wrist, m.lower, m.upper, T[None, :3, 3], T[None, :3, :3], seed[None]
    )  # type: ignore[arg-type]
    assert ok[0] and np.abs(q[0] - res.q).max() < 1e-9


@pytest.mark.parametrize(("xyz", "yaw"), [("0 0 0", 0.0), ("0.25 -0.4 0.1", 0.8)])
def test_recognised_from_a_urdf_in_any_root_frame(tmp_path: Path, xyz: str, yaw: float) -> None:
    m = load_model("puma560")
    text = urdf_of(m).replace(
        '<joint name="waist"',
        f'<joint name="root" type="fixed"><parent link="world"/><child link="base_link"/>'
        f'<origin xyz="{xyz}" rpy="0 0 {yaw}"/></joint><link name="world"/><joint name="waist"',
        1,
    )
    path = tmp_path / "puma.urdf"
    path.write_text(text)
    u = load_model(path)
    assert closed_form(u) == "spherical wrist"
    _, T = targets(u, 500, 5)
    out = ik_batch(u, T[:, :3, 3], orientations=T[:, :3, :3])
    assert out.ok.all() and np.abs(fk(u, out.q) - T).max() < 1e-9
    for i in range(0, 500, 5):
        assert np.abs(fk(u, ik(u, T[i, :3, 3], orientation=T[i, :3, :3]).q) - T[i]).max() < 1e-9


def test_a_wrist_with_an_offset_is_numeric(tmp_path: Path) -> None:
    m = puma_variant(tmp_path, d5=40.0)
    assert closed_form(m) == ""
    T = fk(m, np.radians([10.0, 30.0, -60.0, 20.0, 30.0, 40.0]))
    res = ik(m, T[:3, 3], orientation=T[:3, :3])
    assert res.method == "lm" and np.abs(fk(m, res.q)[:3, 3] - T[:3, 3]).max() < 1e-5


def test_refusals_say_why() -> None:
    m = load_model("puma560")
    with pytest.raises(UnreachableError) as far:
        ik(m, (2.0, 0.0, 0.5), orientation=np.eye(3))
    assert far.value.reason == "too_far"
    with pytest.raises(UnreachableError, match="waist would be") as limit:
        ik(m, (0.3, 0.1, 0.5), orientation=np.eye(3))
    assert limit.value.reason == "joint_limit"
    with pytest.raises(UnreachableError) as close:  # within the 150 mm shoulder offset
        ik(m, (0.05, 0.0, 0.67), orientation=np.eye(3))
    assert close.value.reason == "too_close"
    P = [[2.0, 0.0, 0.5], [0.3, 0.1, 0.5], [0.05, 0.0, 0.67]]
    out = ik_batch(m, P, orientations=np.tile(np.eye(3), (3, 1, 1)))
    assert out.reason.tolist() == ["too_far", "joint_limit", "too_close"]
    assert np.isnan(out.q).all()


@pytest.mark.parametrize(
    "R",
    [np.diag([1.0, 1.0, -1.0]), np.full((3, 3), np.nan), np.eye(3) * 1.01, np.eye(3)[[1, 0, 2]]],
)
def test_orientations_are_checked_as_the_numeric_path_checks_them(R: np.ndarray) -> None:
    m = load_model("puma560")
    with pytest.raises(InputError, match=r"rotation matrix|finite"):
        ik(m, (0.5, 0.0, 0.8), orientation=R)
    with pytest.raises(InputError, match=r"rotation matrix|finite"):
        ik(m, (0.5, 0.0, 0.8), orientation=R, method="lm")


def test_a_near_rotation_is_taken_within_a_micro_radian() -> None:
    m = load_model("puma560")
    T = fk(m, np.radians([10.0, 30.0, -60.0, 20.0, 30.0, 40.0]))
    R = T[:3, :3] * (1 + 4e-7)
    res = ik(m, T[:3, 3], orientation=R)
    assert res.method == "analytic" and res.angle_error < 1e-6
    assert math.isfinite(res.position_error)
