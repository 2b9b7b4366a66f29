"""The plain-float and the lean batch FK + Jacobian agree with armkit.kinematics's own."""

from __future__ import annotations

import numpy as np
import pytest
from numeric_cases import ARMS, joint_vectors

from armkit.kinematics import fk, jacobian
from armkit.kinematics._jacobian import jacobian_and_pose
from armkit.kinematics._numeric._batch_chain import jacobian_and_pose_lean
from armkit.kinematics._numeric._scalar_chain import chain_state, scalar_chain
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
