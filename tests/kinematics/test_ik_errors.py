"""IK refuses what it cannot do, and says why."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from armkit import UnreachableError
from armkit.kinematics import fk, ik, ik_batch, why_no_closed_form
from armkit.model import load_model


def test_too_far_too_close_and_limits() -> None:
    m = load_model("openmanipulator_x")
    with pytest.raises(UnreachableError, match="too far") as far:
        ik(m, (1.0, 0.0, 0.1), -math.pi / 2)
    assert far.value.reason == "too_far"
    with pytest.raises(UnreachableError) as close:
        ik(m, (0.01, 0.0, 0.077), 0.0)
    assert close.value.reason in {"too_close", "joint_limit"}
    with pytest.raises(
        UnreachableError, match=r"(waist|shoulder|elbow|wrist) would be .* allowed"
    ) as lim:
        ik(m, (0.15, 0.0, 0.05), math.pi / 2)  # pointing up from low down: the shoulder cannot
    assert lim.value.reason == "joint_limit"


def test_off_plane_for_planar_arm() -> None:
    m = load_model("planar2")
    with pytest.raises(UnreachableError) as exc:
        ik(m, (0.5, 0.1, 0.5))
    assert exc.value.reason == "off_plane"


def test_planar2_pitch_follows_position() -> None:
    m = load_model("planar2")
    with pytest.raises(
        UnreachableError, match=r"follows from the position.*leave the pitch out"
    ) as exc:
        ik(m, (0.5, 0.0, 0.5), 1.234)
    assert exc.value.reason == "pitch"


def test_on_the_base_axis_the_pitch_is_within_90_deg() -> None:
    m = load_model("openmanipulator_x")
    with pytest.raises(UnreachableError, match=r"base axis .* within -90..90 deg") as exc:
        ik(m, (0.0, 0.0, 0.3), math.radians(120))
    assert exc.value.reason == "pitch"


@pytest.mark.parametrize(
    ("position", "match"),
    [
        ((0.1, float("nan"), 0.1), "finite"),
        ((0.1, math.inf, 0.1), "finite"),
        ((0.1, 0.2), "three numbers"),
        (np.zeros(4), "shape"),
        ("xyz", "three numbers"),
    ],
)
def test_bad_position(position: object, match: str) -> None:
    with pytest.raises(ValueError, match=match):
        ik(load_model("openmanipulator_x"), position)  # type: ignore[arg-type]


def test_bad_pitch_seed_and_method() -> None:
    m = load_model("openmanipulator_x")
    with pytest.raises(ValueError, match="pitch"):
        ik(m, (0.2, 0, 0.1), float("nan"))
    with pytest.raises(ValueError, match="q_seed"):
        ik(m, (0.2, 0, 0.1), 0.0, q_seed=[0, 0])
    with pytest.raises(ValueError, match="method must be one of"):
        ik(m, (0.2, 0, 0.1), 0.0, method="magic")
    with pytest.raises(ValueError, match="positions"):
        ik_batch(m, np.zeros((3, 2)))
    with pytest.raises(ValueError, match="pitches"):
        ik_batch(m, np.zeros((3, 3)), np.zeros(2))


def test_family_is_recognised_from_geometry_not_names(tmp_path: Path) -> None:
    """The OpenManipulator-X rewritten in standard DH is still solved in closed form."""
    text = """
name = "omx_standard"
dh_convention = "standard"
[[joints]]
name = "j1"
limits_deg = [-180, 180]
home_deg = 0
dh = { a_mm = 0, alpha_deg = -90, d_mm = 77 }
[[joints]]
name = "j2"
limits_deg = [-90, 90]
home_deg = 0
dh = { a_mm = 130, alpha_deg = 0, d_mm = 0, theta_offset_deg = -79.38 }
[[joints]]
name = "j3"
limits_deg = [-90, 90]
home_deg = 0
dh = { a_mm = 124, alpha_deg = 0, d_mm = 0, theta_offset_deg = 79.38 }
[[joints]]
name = "j4"
limits_deg = [-100, 110]
home_deg = 0
dh = { a_mm = 126, alpha_deg = 0, d_mm = 0 }
"""
    path = tmp_path / "omx_standard.toml"
    path.write_text(text)
    m = load_model(path)
    assert why_no_closed_form(m) == ""
    q = np.radians([30, 20, -10, 15])
    T = fk(m, q)
    res = ik(m, T[:3, 3], -math.radians(25), q_seed=q)
    assert np.allclose(res.q, q, atol=1e-9)


def test_twisted_arm_is_not_family(tmp_path: Path) -> None:
    text = """
name = "twisted"
dh_convention = "standard"
[[joints]]
name = "a"
limits_deg = [-180, 180]
home_deg = 0
dh = { a_mm = 0, alpha_deg = 90, d_mm = 100 }
[[joints]]
name = "b"
limits_deg = [-180, 180]
home_deg = 0
dh = { a_mm = 100, alpha_deg = 45, d_mm = 0 }
[[joints]]
name = "c"
limits_deg = [-180, 180]
home_deg = 0
dh = { a_mm = 100, alpha_deg = 0, d_mm = 0 }
"""
    path = tmp_path / "twisted.toml"
    path.write_text(text)
    m = load_model(path)
    assert "not a base yaw" in why_no_closed_form(m)
    with pytest.raises(ValueError, match="not a base yaw"):
        ik(m, (0.1, 0.1, 0.1), method="analytic")


def test_limit_message_names_the_nearest_miss() -> None:
    """(200, 0, 50) mm with a level gripper needs the OWI's wrist at about -64.5 deg (limit -60):
    the message names the wrist, not the over-the-shoulder base angle."""
    with pytest.raises(
        UnreachableError, match=r"wrist would be -64\.\d deg, allowed -60\.0\.\.60\.0"
    ):
        ik(load_model("owi535"), (0.2, 0.0, 0.05))


@pytest.mark.parametrize(
    ("position", "reason", "match"),
    [
        ((0.25, 0.0, 0.25), "too_far", "too far away"),  # was "base would be 180.0 deg"
        ((0.15, -0.05, 0.04), "joint_limit", r"wrist would be -86\.6 deg"),  # was the base
        ((0.03, 0.0, 0.05), "joint_limit", r"wrist would be -112\.5 deg"),  # was the base
    ],
)
def test_a_base_out_of_its_limits_the_other_way_round_is_not_the_reason(
    position: tuple[float, float, float], reason: str, match: str
) -> None:
    """The OWI's base turns +-135 deg, so reaching back over the shoulder is closed to it
    for a target ahead; the error says what goes wrong facing the target, in ik and
    ik_batch alike."""
    m = load_model("owi535")
    with pytest.raises(UnreachableError, match=match) as exc:
        ik(m, position)
    assert exc.value.reason == reason
    assert ik_batch(m, [position]).reason.tolist() == [reason]


def test_the_base_is_named_when_no_way_round_fits() -> None:
    """The Lynx6's base turns 15..165 deg: a target straight to its right fits neither way."""
    with pytest.raises(UnreachableError, match=r"base would be 0\.0 deg, allowed 15\.0\.\.165"):
        ik(load_model("lynx6"), (0.0, -0.3, 0.05))


@pytest.mark.parametrize("name", ["owi535", "openmanipulator_x", "lynx6", "al5d", "planar2"])
@pytest.mark.parametrize("pitch", [None, 0.3, 2.0])
def test_batch_reasons_are_the_errors_of_ik(name: str, pitch: float | None) -> None:
    """ik_batch says why a target fails as ik's error does: the same reason, by the same
    ranking (a joint limit in a branch whose base fits first, then too far, too close, the
    pitch, and a base outside its limits last)."""
    m = load_model(name)
    rng = np.random.default_rng(7)
    P = rng.uniform(-0.6, 0.6, (400, 3))
    P[:40, :2] = 0.0  # on the base axis: beyond +-90 deg no pitch is possible there
    if name == "planar2":
        P[:, 1] = 0.0
    batch = ik_batch(m, P, pitch)
    for p, got in zip(P, batch.reason, strict=True):
        try:
            ik(m, p, pitch)
            want = ""
        except UnreachableError as e:
            want = e.reason
        assert got == want, (p, pitch)
