"""The plain-float and the lean batch FK + Jacobian agree with armkit.kinematics's own."""

from __future__ import annotations

import numpy as np
import pytest
from numeric_cases import ARMS, joint_vectors

from armkit.kinematics import fk, jacobian
from armkit.kinematics._jacobian import jacobian_and_pose
from armkit.kinematics._numeric._batch_chain import jacobian_and_pose_lean
from armkit.kinematics._numeric._scalar_chain import chain_state, chain_state_loop, scalar_chain
from armkit.kinematics._numeric._unrolled import source_of
from armkit.model import load_model


@pytest.mark.parametrize("arm", ARMS)
def test_scalar_chain_matches_fk_and_jacobian(arm: str) -> None:
    model = load_model(arm)
    sc = scalar_chain(model)
    for q in joint_vectors(model, 20, seed=1):
        st = chain_state(sc, q.tolist())
        T = fk(model, q)
        J = jacobian(model, q)
        np.testing.assert_allclose(st.p, T[:3, 3], atol=1e-12)
        np.testing.assert_allclose(np.array(st.R).T, T[:3, :3], atol=1e-12)
        np.testing.assert_allclose(np.array(st.jv).T, J[:3], atol=1e-12)
        np.testing.assert_allclose(np.array(st.jw).T, J[3:], atol=1e-12)


@pytest.mark.parametrize("arm", ARMS)
def test_lean_batch_chain_matches_jacobian_and_pose(arm: str) -> None:
    model = load_model(arm)
    q = joint_vectors(model, 30, seed=2)
    J, T = jacobian_and_pose(model, q)
    J2, T2 = jacobian_and_pose_lean(model, q)
    np.testing.assert_allclose(J2, J, atol=1e-12)
    np.testing.assert_allclose(T2, T, atol=1e-12)


@pytest.mark.parametrize("arm", ARMS)
def test_unrolled_chain_state_equals_the_loop_bit_for_bit(arm: str) -> None:
    model = load_model(arm)
    sc = scalar_chain(model)
    for q in joint_vectors(model, 50, seed=7):
        fast, ref = chain_state(sc, q.tolist()), chain_state_loop(sc, q.tolist())
        assert (fast.p, fast.R, fast.jw, fast.origins) == (ref.p, ref.R, ref.jw, ref.origins)
        assert fast.jv == ref.jv


def test_unrolled_source_has_no_loop_and_drops_zero_lengths() -> None:
    sc = scalar_chain(load_model("openmanipulator_x"))
    source = source_of(sc.modified, sc.rows, sc.tool_R, sc.tool_axes, sc.tool_offsets)
    assert "for " not in source
    assert "0.0 * " not in source  # zero a / d terms are not written out
    assert source.count("cos(") == 4
