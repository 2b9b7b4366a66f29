"""The compiled LM kernel (kinematics/_numeric/_lmc.c) pinned to its Python reference
(lm_reference.py, the same method step for step, the same restart sequence): on fixed
seeds both converge on the same targets, after the same restarts, to the same joint
vector; a batch row is the single call on that target; a 7-joint chain and a chain
with joints at their limits are solved the same way."""

from __future__ import annotations

import math
from pathlib import Path

import lm_reference
import numpy as np
import pytest
from numeric_cases import ARMS, TOL_ANG, TOL_POS, assert_reaches, joint_vectors, masks_for

from armkit.kinematics import Target, fk, ik_batch, pitch_of
from armkit.kinematics._chain import chain_of
from armkit.kinematics._numeric._lm import solve_lm
from armkit.kinematics._residual import Task
from armkit.model import ArmModel, load_model


def _tasks(model: ArmModel, mask: str, n: int, seed: int) -> list[Task[float]]:
    T = fk(model, joint_vectors(model, n, seed))
    out = []
    for t in T:
        p = tuple(t[:3, 3].tolist())
        pitch = float(pitch_of(t)) if mask == "position+pitch" else None
        R = tuple(t[:3, :3].ravel().tolist()) if mask == "pose" else None
        out.append(Task(p, pitch, R, chain_of(model).weight))  # type: ignore[arg-type]
    return out


def _seeds(model: ArmModel, n: int) -> list[list[float]]:
    """Home, then joint vectors at and beyond the limits (clamped by both solvers)."""
    wide = np.random.default_rng(9).uniform(model.lower - 0.5, model.upper + 0.5, (n, model.dof))
    return [model.home.tolist(), *wide.tolist()][:n]


@pytest.mark.parametrize("arm", ARMS)
def test_the_kernel_follows_the_reference_step_for_step(arm: str) -> None:
    """Same convergence, restarts and iterations on (nearly) every target, the same q where
    they agree; never a success rate apart by more than one target in 40."""
    model = load_model(arm)
    chain = chain_of(model)
    same = total = 0
    for mask in masks_for(model):
        tasks, seeds = _tasks(model, mask, 40, seed=11), _seeds(model, 40)
        ok_kernel = ok_ref = 0
        for rng_seed, (task, seed) in enumerate(zip(tasks, seeds, strict=True)):
            a = solve_lm(chain, task, seed, TOL_POS, TOL_ANG, rng_seed)
            b = lm_reference.solve_lm(chain, task, seed, TOL_POS, TOL_ANG, rng_seed)
            ok_kernel += a.converged
            ok_ref += b.converged
            total += 1
            if (a.converged, a.restarts, a.iterations) == (b.converged, b.restarts, b.iterations):
                same += 1
                np.testing.assert_allclose(a.q, b.q, atol=1e-7)
                assert a.residual.position_error == pytest.approx(
                    b.residual.position_error, rel=1e-5, abs=1e-12
                )
        assert abs(ok_kernel - ok_ref) <= 1, (mask, ok_kernel, ok_ref)
    assert same >= 0.95 * total, f"{same} of {total} runs alike"


@pytest.mark.parametrize(("arm", "mask"), [("puma560", "pose"), ("lynx6", "position+pitch")])
def test_a_batch_row_is_the_single_call(arm: str, mask: str) -> None:
    model = load_model(arm)
    chain = chain_of(model)
    tasks = _tasks(model, mask, 30, seed=12)
    P = np.array([t.p for t in tasks])
    pitch = np.array([t.pitch for t in tasks]) if mask == "position+pitch" else None
    R = np.array([t.R for t in tasks]).reshape(-1, 3, 3) if mask == "pose" else None
    seeds = np.array(_seeds(model, 30))
    out = ik_batch(
        model, P, pitch, seeds, orientations=R, method="lm", tol_m=TOL_POS, tol_rad=TOL_ANG
    )
    for i, task in enumerate(tasks):
        one = solve_lm(chain, task, seeds[i].tolist(), TOL_POS, TOL_ANG, 0)
        assert out.ok[i] == one.converged
        if one.converged:
            assert out.q[i].tolist() == one.q


PANDA = [  # Franka Panda's modified DH rows: a, d [mm], alpha, lower, upper [deg]
    (0.0, 333.0, 0.0, -166.0, 166.0),
    (0.0, 0.0, -90.0, -101.0, 101.0),
    (0.0, 316.0, 90.0, -166.0, 166.0),
    (82.5, 0.0, 90.0, -176.0, -4.0),
    (-82.5, 384.0, -90.0, -166.0, 166.0),
    (0.0, 0.0, 90.0, -1.0, 215.0),
    (88.0, 0.0, 90.0, -166.0, 166.0),
]


def _panda_urdf(folder: Path) -> Path:
    """A 7-joint URDF with Panda's numbers: each row a joint origin Rx(alpha) Tx(a) Tz(d)."""
    joints, parent = [], "base"
    for i, (a, d, al, lo, hi) in enumerate(PANDA):
        c, s = math.cos(math.radians(al)), math.sin(math.radians(al))
        joints.append(
            f'<joint name="j{i + 1}" type="revolute"><parent link="{parent}"/>'
            f'<child link="l{i + 1}"/><origin xyz="{a / 1000} {-s * d / 1000} {c * d / 1000}" '
            f'rpy="{math.radians(al)} 0 0"/><axis xyz="0 0 1"/><limit lower="{math.radians(lo)}" '
            f'upper="{math.radians(hi)}" effort="1" velocity="1"/></joint><link name="l{i + 1}"/>'
        )
        parent = f"l{i + 1}"
    path = folder / "panda.urdf"
    path.write_text(
        '<?xml version="1.0"?><robot name="panda"><link name="base"/>' + "".join(joints)
        + '<joint name="flange" type="fixed"><parent link="l7"/><child link="tool"/>'
        '<origin xyz="0 0 0.107" rpy="0 0 0"/></joint><link name="tool"/></robot>'
    )  # fmt: skip
    return path


def test_a_seven_joint_urdf_follows_the_reference_and_reaches_full_poses(tmp_path: Path) -> None:
    model = load_model(_panda_urdf(tmp_path))
    chain = chain_of(model)
    assert model.dof == 7 and chain.wrist is None and chain.family is None
    alike = 0
    for k, task in enumerate(_tasks(model, "pose", 20, seed=13)):
        a = solve_lm(chain, task, model.home.tolist(), TOL_POS, TOL_ANG, k)
        b = lm_reference.solve_lm(chain, task, model.home.tolist(), TOL_POS, TOL_ANG, k)
        assert a.converged
        alike += (a.restarts, a.iterations) == (b.restarts, b.iterations)
        R = np.array(task.R).reshape(3, 3)
        assert_reaches(model, np.array(a.q), Target(np.array(task.p), None, R), TOL_POS, TOL_ANG)
    assert alike >= 18
