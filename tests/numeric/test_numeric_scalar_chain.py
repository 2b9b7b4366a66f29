"""The generated chain code, on floats and on lanes, agrees with the dense product of the
steps' transforms (``fk_frames``), the reference; the Jacobian with finite differences."""

from __future__ import annotations

import math

import numpy as np
import pytest
from numeric_cases import ARMS, joint_vectors

from armkit.kinematics import fk, fk_frames, jacobian
from armkit.kinematics._chain import chain_of
from armkit.kinematics._state import source_of
from armkit.model import load_model


@pytest.mark.parametrize("arm", ARMS)
def test_generated_code_matches_the_dense_product(arm: str) -> None:
    model = load_model(arm)
    chain = chain_of(model)
    qs = joint_vectors(model, 20, seed=1)
    T = fk(model, qs)  # the lanes
    J = jacobian(model, qs)
    for i, q in enumerate(qs):
        ref = fk_frames(model, q)[-1]
        st = chain.state(q.tolist())
        np.testing.assert_allclose(st.p, ref[:3, 3], atol=1e-12)
        np.testing.assert_allclose(np.array(st.R).T, ref[:3, :3], atol=1e-12)
        np.testing.assert_allclose(T[i], ref, atol=1e-12)
        np.testing.assert_allclose(np.array(st.jv).T, J[i, :3], atol=1e-12)
        np.testing.assert_allclose(np.array(st.jw).T, J[i, 3:], atol=1e-12)
        np.testing.assert_allclose(jacobian(model, q), J[i], atol=1e-15)
        h = 1e-6  # the linear rows against central differences of the tool point
        for k in range(model.dof):
            d = np.zeros(model.dof)
            d[k] = h
            diff = (fk(model, q + d)[:3, 3] - fk(model, q - d)[:3, 3]) / (2 * h)
            np.testing.assert_allclose(J[i, :3, k], diff, atol=1e-8)


def test_source_has_no_loop_and_drops_zero_lengths() -> None:
    chain = chain_of(load_model("openmanipulator_x"))
    source = source_of(chain.steps, chain.tool)
    assert "for " not in source
    assert "0.0 * " not in source  # zero terms are not written out
    assert source.count("cos(") == 4


def test_general_joint_axes_agree_with_dh() -> None:
    """The same arm given as joint frames (axes along y, as URDF has them) has the same FK."""
    from dataclasses import replace

    from armkit.kinematics._steps import frames_of

    model = load_model("lynx6")
    frames = frames_of(chain_of(model).steps)
    turned = []
    for f in frames:  # express each joint about its frame's y axis instead of z
        R = np.eye(4)
        c, s = math.cos(math.pi / 2), math.sin(math.pi / 2)
        R[:3, :3] = [[1, 0, 0], [0, c, -s], [0, s, c]]
        turned.append(replace(f, origin=f.origin @ R, axis=(0.0, f.axis[2], 0.0)))
    # undo each turn in the next frame / the tool
    fixed = []
    for k, f in enumerate(turned):
        back = np.eye(4)
        if k > 0:
            back[:3, :3] = [[1, 0, 0], [0, 0, 1], [0, -1, 0]]
        fixed.append(replace(f, origin=back @ f.origin))
    back = np.eye(4)
    back[:3, :3] = [[1, 0, 0], [0, 0, 1], [0, -1, 0]]
    general = replace(
        model, convention="frames", dh=(), frames=tuple(fixed),
        T_flange_tool=back @ chain_of(model).tool.T,
    )  # fmt: skip
    q = joint_vectors(model, 50, seed=3)
    np.testing.assert_allclose(fk(general, q), fk(model, q), atol=1e-12)
    np.testing.assert_allclose(jacobian(general, q), jacobian(model, q), atol=1e-12)
    assert chain_of(general).family is not None  # recognised from the axes, not DH fields
