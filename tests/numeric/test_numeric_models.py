"""The two arms shipped for the numeric solver: AL5D and PUMA 560."""

from __future__ import annotations

import numpy as np
from numeric_cases import TOL_ANG, TOL_POS, assert_reaches, target_for

from armkit.kinematics import closed_form, fk, ik, why_no_closed_form
from armkit.model import load_model


def test_puma560_matches_the_toolbox_qz_and_qr_poses() -> None:
    model = load_model("puma560")
    assert model.dof == 6 and model.convention == "standard"
    # Robotics Toolbox 1.5.0's DH Puma560 (base = 26.45 inch = 0.67183 m): fkine(qz) =
    # (0.4521, -0.15005, 1.10363); fkine(qr) = (0.0203, -0.15005, 1.53543)
    np.testing.assert_allclose(
        fk(model, np.zeros(6))[:3, 3], [0.4521, -0.15005, 1.10363], rtol=0, atol=1e-12
    )
    qr = np.array([0.0, np.pi / 2, -np.pi / 2, 0.0, 0.0, 0.0])
    np.testing.assert_allclose(
        fk(model, qr)[:3, 3], [0.0203, -0.15005, 1.53543], rtol=0, atol=1e-12
    )


def test_al5d_home_is_the_l_pose_with_a_level_hand() -> None:
    model = load_model("al5d")
    T = fk(model, model.home)
    np.testing.assert_allclose(T[:3, 3], [0.187325 + 0.1, 0.0, 0.06731 + 0.14605], atol=1e-9)
    np.testing.assert_allclose(T[:3, :3], np.eye(3), atol=1e-9)


def test_the_puma_gets_the_spherical_wrist_closed_form_and_lm_on_request() -> None:
    model = load_model("puma560")
    assert why_no_closed_form(model) and closed_form(model) == "spherical wrist"
    target = target_for(model, np.radians([30.0, 100.0, -150.0, 20.0, 40.0, 10.0]), "pose")
    for method in ("auto", "lm"):
        result = ik(model, target.position, orientation=target.orientation, method=method)
        assert result.method == ("lm" if method == "lm" else "analytic")
        assert_reaches(model, result.q, target, TOL_POS, TOL_ANG)
