"""The drawing's fast paths give what their references give (issue 29 item 5).

- ``densify`` (all pieces at once) = ``densify_loop`` (piece by piece);
- ``scene.joint_sweeps`` (K moves at once) = ``joint_sweep`` per move;
- ``motion.chained_ik`` (a few batches) = the loop of ``ik``, each point seeded by
  the previous one's solution;
- ``reachable_runs`` = ``reachable_runs_loop`` and ``plan_strokes`` (batches) =
  ``plan_strokes_loop`` (stroke by stroke) on the shipped drawings;
- the Or-opt moves applied at once (``_apply_moves``) = the same moves one by one.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from armkit import load_model
from armkit.drawing import DrawOptions
from armkit.drawing._job import _reachable, find_pen, find_sheet, make_rig, plan_on_sheet
from armkit.drawing._pen import pick_pen, stand_of
from armkit.drawing._reach import densify, densify_loop, reachable_runs, reachable_runs_loop
from armkit.drawing._rig import plan_strokes, plan_strokes_loop
from armkit.drawing._segments_job import JointMove, PathMove, end_q
from armkit.drawing._tour import _apply_moves, move
from armkit.kinematics import ik
from armkit.motion import chained_ik
from armkit.scene import joint_sweep, joint_sweeps, load_scene

DRAWINGS = Path(__file__).resolve().parents[2] / "examples" / "drawings"


def test_densify_equals_its_loop() -> None:
    rng = np.random.default_rng(3)
    for _ in range(200):
        stroke = np.cumsum(rng.normal(0, 0.004, size=(int(rng.integers(1, 12)), 3)), axis=0)
        if rng.random() < 0.2 and len(stroke) > 2:
            stroke[1] = stroke[0]  # a zero-length piece
        np.testing.assert_array_equal(densify(stroke), densify_loop(stroke))


def test_joint_sweeps_equal_joint_sweep_per_move() -> None:
    rng = np.random.default_rng(4)
    a, b = rng.uniform(-2, 2, size=(50, 4)), rng.uniform(-2, 2, size=(50, 4))
    b[7] = a[7]  # a move of zero length
    want = np.vstack([joint_sweep(a[k], b[k][None]) for k in range(len(a))])
    np.testing.assert_array_equal(joint_sweeps(a, b), want)


@pytest.mark.parametrize("arm", ["openmanipulator_x", "lynx6"])
def test_chained_ik_equals_the_loop_of_ik(arm: str) -> None:
    model = load_model(arm)
    t = np.linspace(0, 2 * math.pi, 400)
    points = np.column_stack([0.2 + 0.04 * np.cos(t), 0.04 * np.sin(3 * t), 0.03 + 0.0 * t])
    pitch = -math.pi / 3
    q0 = np.zeros(model.dof)
    got = chained_ik(model, points, pitch, q0)
    assert got is not None
    seed, want = q0, []
    for p in points:
        seed = ik(model, p, pitch, seed).q
        want.append(seed)
    np.testing.assert_allclose(got, np.array(want), atol=1e-9)
    far = points.copy()
    far[200] = [5.0, 0.0, 0.0]
    assert chained_ik(model, far, pitch, q0) is None  # the loop says why


def _job_parts(arm: str, file: str):  # type: ignore[no-untyped-def]
    model = load_model(arm)
    scene = load_scene("drawing")
    opts = DrawOptions()
    plan = plan_on_sheet(scene, DRAWINGS / file, options=opts)
    sheet, pen = find_sheet(scene, None), find_pen(scene, None)
    rig = make_rig(model, scene, sheet, pen, opts)
    stand = stand_of(scene, pen)
    assert stand is not None
    q = end_q(
        pick_pen(rig, stand, pen, model.home.copy(), opts.clearance / 1000.0), model.home.copy()
    )
    return rig, plan, q


@pytest.mark.parametrize("arm", ["openmanipulator_x", "lynx6"])
@pytest.mark.parametrize("file", ["lines.svg", "curve.svg"])
def test_fast_drawing_plan_equals_the_stroke_by_stroke_one(arm: str, file: str) -> None:
    rig, plan, q = _job_parts(arm, file)
    args = (rig.tip, list(plan.strokes), rig.sheet.to_world, rig.scene.to_base, rig.pitch, q)
    lift = rig.sheet.normal * rig.pen_up
    runs, cut, total = reachable_runs(*args, lift)
    ref, ref_cut, ref_total = reachable_runs_loop(*args, lift)
    assert len(runs) == len(ref)
    assert cut == pytest.approx(ref_cut, abs=1e-12) and total == pytest.approx(ref_total)
    for a, b in zip(runs, ref, strict=True):
        np.testing.assert_array_equal(a.uv, b.uv)
        np.testing.assert_allclose(a.q, b.q, atol=1e-9)
    runs, _ = _reachable(rig, plan, q, arm)
    fast, slow = plan_strokes(rig, runs, q), plan_strokes_loop(rig, runs, q)
    assert len(fast) == len(slow)
    for a, b in zip(fast, slow, strict=True):
        assert type(a) is type(b) and a.label == b.label
        if isinstance(a, JointMove) and isinstance(b, JointMove):
            np.testing.assert_allclose(a.q, b.q, atol=1e-9)
        if isinstance(a, PathMove) and isinstance(b, PathMove):
            assert a.draws == b.draws
            np.testing.assert_allclose(a.path.points, b.path.points, atol=1e-12)
            np.testing.assert_allclose(a.path.q, b.path.q, atol=1e-9)


def _moved(order, flip, moves):  # type: ignore[no-untyped-def]
    """The reference: walk the positions, leave the moved runs out, put each after its q."""
    out: list[tuple[int, bool]] = []
    taken = {k for p, _, size, _ in moves for k in range(p, p + size)}
    after: dict[int, list[tuple[int, bool]]] = {}
    for p, q, size, rev in moves:
        run = [(int(order[k - 1]), bool(flip[k - 1])) for k in range(p, p + size)]
        after[q] = [(s, not f) for s, f in reversed(run)] if rev else run
    out += after.get(0, [])
    for k in range(1, len(order) + 1):
        if k not in taken:
            out.append((int(order[k - 1]), bool(flip[k - 1])))
        out += after.get(k, [])
    return np.array([s for s, _ in out]), np.array([f for _, f in out])


def test_or_opt_moves_at_once_equal_one_by_one() -> None:
    rng = np.random.default_rng(5)
    n = 40
    for _ in range(200):
        order, flip = rng.permutation(n), rng.random(n) < 0.5
        p, size = int(rng.integers(1, 10)), int(rng.integers(1, 4))
        q, rev = int(rng.choice([0, *range(20, 30)])), bool(rng.random() < 0.5)
        moves = [(p, q, size, rev), (14, int(rng.choice([33, 40])), 2, not rev)]
        got_o, got_f = order.copy(), flip.copy()
        _apply_moves(got_o, got_f, moves)
        want_o, want_f = _moved(order, flip, moves)
        np.testing.assert_array_equal(got_o, want_o)
        np.testing.assert_array_equal(got_f, want_f)
        one_o, one_f = order.copy(), flip.copy()
        move(one_o, one_f, p, q, size, rev)  # one move: as the in-place reference moves it
        _apply_moves(order, flip, moves[:1])
        np.testing.assert_array_equal(order, one_o)
        np.testing.assert_array_equal(flip, one_f)
