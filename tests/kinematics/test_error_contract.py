"""The kinematics error contract (issue 10 items 2 and 5): every user-caused error is an
ArmkitError (an InputError, also a ValueError, for a bad value), reasons are the
documented Literal, empty batches give empty results, messages stay short and in the
user's terms, and degenerate links never reach a ZeroDivisionError."""

from __future__ import annotations

import math
import typing
from dataclasses import replace

import numpy as np
import pytest

from armkit import ArmkitError, ModelError, UnreachableError
from armkit._errors import InputError, Reason
from armkit.cli import main
from armkit.kinematics import Target, fk, fk_frames, ik, ik_batch, jacobian, why_no_closed_form
from armkit.model import DHRow, load_model

OMX = load_model("openmanipulator_x")


@pytest.mark.parametrize("position", [(None, 0, 0), [None, 0, 0], ("a", 0, 0), (True, 0, 0)])
def test_a_tuple_and_a_list_fail_alike(position: object) -> None:
    with pytest.raises(InputError, match=r"position must be three numbers \(x, y, z\) \[m\]") as e:
        ik(OMX, position)  # type: ignore[arg-type]
    assert isinstance(e.value, ValueError) and isinstance(e.value, ArmkitError)


@pytest.mark.parametrize("method", ["auto", "analytic", "lm"])
@pytest.mark.parametrize("arm", ["openmanipulator_x", "puma560"])
def test_empty_batch_gives_an_empty_result(arm: str, method: str) -> None:
    m = load_model(arm)
    if method == "analytic" and why_no_closed_form(m):
        pytest.skip("no closed form")
    res = ik_batch(m, np.zeros((0, 3)), method=method)  # type: ignore[arg-type]
    assert res.q.shape == (0, m.dof) and res.ok.shape == (0,) and res.reason.shape == (0,)


CALLS = [
    lambda: fk(OMX, [0.0, 0.0]),
    lambda: fk(OMX, "abcd"),
    lambda: fk_frames(OMX, np.zeros((2, 3))),
    lambda: jacobian(OMX, [np.nan] * 4),
    lambda: ik(OMX, (0.2, 0.0, 0.1), pitch="up"),
    lambda: ik(OMX, (0.2, 0.0, 0.1), pitch=np.float64(np.nan)),
    lambda: ik(OMX, (0.2, 0.0, 0.1), q_seed=np.zeros(3)),
    lambda: ik(OMX, (0.2, 0.0, 0.1), method="magic"),
    lambda: ik(OMX, (0.2, 0.0, 0.1), orientation=np.eye(3) * 2, method="lm"),
    lambda: ik(OMX, (0.2, 0.0, 0.1), method="lm", tol_m=-1.0),
    lambda: ik(OMX, (0.2, 0.0, 0.1), tol_m=-1.0),  # the closed form took it unchecked
    lambda: ik(OMX, (0.2, 0.0, 0.1), 0.0, tol_rad=np.nan),
    lambda: ik_batch(OMX, np.zeros((3, 3)) + 0.2, tol_m="fine"),
    lambda: ik(OMX, Target((0.2, 0.0, 0.1), 0.1), 0.2),
    lambda: ik(OMX, np.array([0.2, np.nan, 0.1])),
    lambda: ik_batch(OMX, np.zeros((3, 2))),
    lambda: ik_batch(OMX, np.zeros((3, 3)), np.zeros(2)),
    lambda: ik_batch(OMX, np.zeros((3, 3)), q_seed=np.zeros((2, 4))),
    lambda: ik_batch(OMX, np.full((3, 3), np.inf)),
    lambda: ik_batch(OMX, np.zeros((3, 3)), method="ccd"),
]


@pytest.mark.parametrize("call", CALLS)
def test_bad_values_are_input_errors_with_short_messages(call: typing.Callable[[], object]) -> None:
    with pytest.raises(InputError) as e:
        call()
    text = str(e.value)
    assert isinstance(e.value, ValueError)
    assert "np.float64" not in text and "array(" not in text and len(text) < 200
    assert not any(len(tok) > 20 and tok.strip("-.").isdigit() for tok in text.split())


def test_reasons_are_the_documented_literal() -> None:
    allowed = set(typing.get_args(Reason))
    assert {
        "too_far",
        "too_close",
        "joint_limit",
        "off_plane",
        "pitch",
        "no_convergence",
    } <= allowed
    P = np.array([[2.0, 0, 0], [0.2, 0, 0.05], [0.0, 0.0, 0.077], [1e308, 0, 0]])
    res = ik_batch(OMX, P, np.full(4, -math.pi / 2))
    assert set(res.reason.tolist()) <= allowed | {""}
    with pytest.raises(UnreachableError) as e:
        ik(OMX, (1e308, 0.0, 0.0))
    assert e.value.reason == "too_far" and e.value.reason in allowed
    assert "(1e+308, 0, 0) m" in str(e.value) and len(str(e.value)) < 200


def test_huge_target_at_the_cli_is_one_short_line(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["ik", "1e308", "0", "0"]) == 2
    err = capsys.readouterr().err
    assert (
        err.count("\n") == 1
        and ("too far" in err or "argument X" in err)
        and len(err) < 200
        and "nan" not in err
    )
    assert main(["ik", "200", "0", "50", "--pitch", "1e308"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "--pitch" in err and "deg" in err and len(err) < 120


@pytest.mark.parametrize("row", [1, 2, 3])
def test_a_link_of_1e300_m_is_refused_clearly(row: int) -> None:
    dh = list(OMX.dh)
    dh[row] = replace(dh[row], a=1e300)
    m = replace(OMX, dh=tuple(dh))
    for call in (
        lambda: fk(m, m.home),
        lambda: ik(m, (0.2, 0.0, 0.1)),
        lambda: ik_batch(m, np.zeros((1, 3))),
    ):
        with pytest.raises(ModelError, match=r"links add up to 1e\+300 m.*up to 10 km"):
            call()


@pytest.mark.parametrize("length", [0.0, 5e3])
@pytest.mark.parametrize("row", [2, 3])
def test_degenerate_links_never_divide_by_zero(length: float, row: int) -> None:
    """A link of length 0 or 5 km: the closed form refuses the arm where its law of cosines
    would (numeric IK takes over) and every call ends in an answer or an ArmkitError."""
    dh = list(OMX.dh)
    dh[row] = replace(dh[row], a=length)
    m = replace(OMX, dh=tuple(dh))
    assert "planar link" in why_no_closed_form(m) or why_no_closed_form(m) == ""
    if why_no_closed_form(m):
        with pytest.raises(InputError, match="does not apply"):
            ik(m, (0.2, 0.0, 0.1), 0.0, method="analytic")
    fk(m, m.home)
    for target in [(0.2, 0.0, 0.1), (0.0, 0.0, 0.0), (1e308, 0.0, 0.0)]:
        try:
            res = ik(m, target, 0.0)
        except ArmkitError:
            continue
        assert np.all(np.isfinite(res.q))
    batch = ik_batch(m, np.array([[0.2, 0.0, 0.1], [0.0, 0.0, 0.0]]))
    assert batch.q.shape == (2, 4)


def test_zero_length_link_in_the_planar_pair() -> None:
    dh = list(OMX.dh)
    dh[2] = DHRow(a=0.0, alpha=0.0, d=0.0, theta_offset=dh[2].theta_offset)
    m = replace(OMX, dh=tuple(dh))
    assert "planar link 1" in why_no_closed_form(m)  # joints 2 and 3 coincide


def test_one_target_type_for_ik_and_ik_batch() -> None:
    q = np.radians([10.0, 5.0, 10.0, 20.0])
    T = fk(OMX, q)
    pitch = float(np.arctan2(T[2, 0], np.hypot(T[0, 0], T[1, 0])))
    one = ik(OMX, Target(T[:3, 3], pitch), q_seed=q)
    assert np.allclose(one.q, q, atol=1e-9)
    many = ik_batch(OMX, Target(np.array([T[:3, 3]] * 3), pitch), q_seed=q)
    assert many.ok.all() and np.allclose(many.q, q, atol=1e-9)
    puma = load_model("puma560")
    Tp = fk(puma, np.radians([30.0, 100.0, -150.0, 20.0, 40.0, 10.0]))
    pose = ik(puma, Target(Tp[:3, 3], orientation=Tp[:3, :3]), method="lm")
    assert pose.method == "lm" and pose.position_error < 1e-5
    with pytest.raises(InputError, match="not both"):
        ik_batch(OMX, Target(np.zeros((1, 3)), 0.1), 0.2)
