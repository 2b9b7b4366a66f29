"""The one rule for refusing a move on clearance: ``Arm`` and ``armkit check`` both ask it.

A move from a pose that is already in collision (an interrupted job left the pen's
holder in the paper, a timed arm's estimate drifted below the table) is a way out
when it only takes the arm out: along its sweep the deepest penetration never grows
and stays in the same object until the arm is clear, and it stays clear after that.
Any other move from there is refused, naming the way out (straight up first).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from .._errors import UnreachableError
from ..model import ArmModel
from ._clearance import COLUMN, Collision, Held, check_clear, joint_sweep
from ._scene import Scene

GROW_TOLERANCE = 2e-5  # [m] a penetration "grows" by more than this (sampling noise below)
WAY_OUT = "move straight up out of it first ('home' does)"


def move_refusal(
    model: ArmModel, q_from: ArrayLike | None, path: ArrayLike, scene: Scene | None,
    held: Held | None = None, opening: float | None = None,
) -> UnreachableError | None:  # fmt: skip
    """Why a joint move from ``q_from`` (dof,) [rad] through the poses ``path`` (K, dof)
    [rad] is refused, or None if it is clear: a link, or the ``held`` cube, below the
    table, into the base column or into the scene's objects (``check_clear``) at a pose
    of the path ("there"), or between them, sampled in joint space ("on the way"; not
    checked when ``q_from`` is None: not known). Jaws open to ``opening`` [m] (None: not
    known) pass over a cube narrower than that: the gripper is not checked against it
    (lowering open jaws over a cube to take it, or lifting them off one let go). From a
    pose already in collision, only a way out is allowed (see the module doc)."""
    ignore = straddled(scene, opening)
    if q_from is not None:
        inside = check_clear(model, q_from, scene, held, ignore=ignore)
        if inside is not None:
            sweep = joint_sweep(q_from, path)
            return _not_a_way_out(model, sweep, scene, held, ignore, inside)
    hit, where = check_clear(model, path, scene, held, ignore=ignore), "there"
    if hit is None and q_from is not None:
        sweep = joint_sweep(q_from, path)
        hit, where = check_clear(model, sweep, scene, held, ignore=ignore), "on the way"
    if hit is None:
        return None
    return UnreachableError(
        f"move refused: {where}, {hit.describe()}; {_remedy(hit)}",
        reason="table" if hit.object == "table" else "collision",
    )


def is_inside(
    model: ArmModel, q: ArrayLike, scene: Scene | None, held: Held | None = None,
    opening: float | None = None,
) -> Collision | None:  # fmt: skip
    """How the pose ``q`` [rad] is already in collision (the deepest), or None: clear."""
    return check_clear(model, q, scene, held, ignore=straddled(scene, opening))


def _not_a_way_out(
    model: ArmModel, sweep: np.ndarray, scene: Scene | None, held: Held | None,
    ignore: frozenset[str], inside: Collision,
) -> UnreachableError | None:  # fmt: skip
    """None if the ``sweep`` (N, dof) from a pose ``inside`` something only takes the arm
    out of it; else why not, naming the way out."""
    depth, out = inside.distance, False
    for k, q in enumerate(sweep):
        hit = check_clear(model, q, scene, held, ignore=ignore)
        if hit is None:
            out = True
            continue
        if out or hit.object != inside.object or hit.distance < depth - GROW_TOLERANCE:
            what = "then hits" if out or hit.object != inside.object else "goes deeper:"
            return UnreachableError(
                f"move refused: the arm starts {-inside.distance * 1000:.1f} mm into the "
                f"{inside.object} ({inside.link}) and this move {what} {hit.describe()}"
                f"{' on the way' if k + 1 < len(sweep) else ''}; {WAY_OUT}",
                reason="table" if hit.object == "table" else "collision",
            )
        depth = hit.distance
    return None


def straddled(scene: Scene | None, opening: float | None) -> frozenset[str]:
    """The cubes of ``scene`` that jaws open to ``opening`` [m] pass over."""
    if scene is None or opening is None:
        return frozenset()
    return frozenset(c.name for c in scene.cubes if c.size < opening)


def _remedy(hit: Collision) -> str:
    if hit.object == COLUMN:
        return "choose a point further from the base"
    return "choose a higher point or another way"
