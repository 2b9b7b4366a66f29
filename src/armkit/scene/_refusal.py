"""The one rule for refusing a move on clearance: ``Arm`` and ``armkit check`` both ask it."""

from __future__ import annotations

from numpy.typing import ArrayLike

from .._errors import UnreachableError
from ..model import ArmModel
from ._clearance import COLUMN, Collision, Held, check_clear, joint_sweep
from ._scene import Scene


def move_refusal(
    model: ArmModel, q_from: ArrayLike | None, path: ArrayLike, scene: Scene | None,
    held: Held | None = None,
) -> UnreachableError | None:  # fmt: skip
    """Why a joint move from ``q_from`` (dof,) [rad] through the poses ``path`` (K, dof)
    [rad] is refused, or None if it is clear: a link, or the ``held`` cube, below the
    table, into the base column or into the scene's objects (``check_clear``) at a pose
    of the path ("there"), or between them, sampled in joint space ("on the way"; not
    checked when ``q_from`` is None: not known)."""
    hit, where = check_clear(model, path, scene, held), "there"
    if hit is None and q_from is not None:
        hit, where = check_clear(model, joint_sweep(q_from, path), scene, held), "on the way"
    if hit is None:
        return None
    return UnreachableError(
        f"move refused: {where}, {hit.describe()}; {_remedy(hit)}",
        reason="table" if hit.object == "table" else "collision",
    )


def _remedy(hit: Collision) -> str:
    if hit.object == COLUMN:
        return "choose a point further from the base"
    return "choose a higher point or another way"
