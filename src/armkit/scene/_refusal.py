"""The one rule for refusing a move on clearance: ``Arm`` and ``armkit check`` both ask it."""

from __future__ import annotations

from numpy.typing import ArrayLike

from .._errors import UnreachableError
from ..model import ArmModel
from ._clearance import COLUMN, Collision, Held, check_clear, joint_sweep
from ._scene import Scene


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
    (lowering open jaws over a cube to take it, or lifting them off one let go)."""
    ignore = straddled(scene, opening)
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


def straddled(scene: Scene | None, opening: float | None) -> frozenset[str]:
    """The cubes of ``scene`` that jaws open to ``opening`` [m] pass over."""
    if scene is None or opening is None:
        return frozenset()
    return frozenset(c.name for c in scene.cubes if c.size < opening)


def _remedy(hit: Collision) -> str:
    if hit.object == COLUMN:
        return "choose a point further from the base"
    return "choose a higher point or another way"
