"""000's moveItem for an item known only by its grip point (no object in the
scene): open, come down to A, close, lift, carry, come down to B, open, leave."""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from ._choose import first_that_works, pitches
from ._grasping import how
from ._state import Context, State, down, grip, up

F64 = NDArray[np.float64]


def move_point(ctx: Context, st: State, a: F64, b: F64, pitch: float | None) -> State:
    """Carry the item whose grip point is ``a`` to ``b`` (scene frame) [m], at the
    first pitch that works for both ends (the model's default on the OWI, 000)."""
    g = ctx.model.gripper
    kin = ctx.model.with_grip_width(g.width_min)

    def at(p: float) -> State:
        s = grip(ctx, st, g.width_max, "open")
        s = down(ctx, s, a, p, f"to A {how(p)}", kin=kin, ignore=frozenset())
        s = grip(ctx, s, g.width_min, "grasp the item")
        s = up(ctx, s, a, p, f"lift the item {how(p)}", kin=kin, ignore=frozenset())
        s = down(ctx, s, b, p, f"put it down at B {how(p)}", kin=kin, ignore=frozenset())
        s = grip(ctx, s, g.width_max, "release the item")
        return up(ctx, s, b, p, f"leave B {how(p)}", kin=kin, ignore=frozenset())

    tries = [(how(p), lambda s, p=p: at(p)) for p in pitches(ctx, pitch)]
    return first_that_works(ctx, st, "carry the item from A to B", tries)
