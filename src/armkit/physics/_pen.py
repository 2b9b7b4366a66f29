"""The pen on the paper under MuJoCo: ``MujocoPenTracer``, the drawing's pen tracer
(``armkit.drawing.PenTracer``'s interface: ``holding``) with MuJoCo as the judge of
ink. The held pen is a capsule on the hand ending at the pen's tip; the arm follows
the simulated servos as under ``MujocoPhysics``; ink is where MuJoCo has the pen
touching the table inside the sheet (the sheet lies on the table), at the tip where
MuJoCo has it (the arm pushed back by the table, not through it). While the pen is
held the jaws touch nothing: 001's pen holder replaces the fingers, and on the
OpenManipulator-X the pen's tip is 10 mm behind the gripper's tool point."""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import NDArray

from ..kinematics import fk
from ..model import ArmModel
from ..scene import Scene, Sheet
from ._engine import Engine

F64 = NDArray[np.float64]
PEN_RADIUS = 0.004  # [m] the pen's writing end
INK = 0.5e-3  # [m]: MuJoCo reports the pen within this of the table (ink, as the rules'
# tracer's 0.5 mm); it pushes back only once they touch (margin = gap)
PEN_FRICTION = 0.2  # a felt tip on paper (its contacts take this, not the table's 1.0)
PEN_CONTYPE = 4  # touches the table and the scene's bodies, not the arm's links


class MujocoPenTracer:
    """Attach to the World (``armkit.drawing.run_job`` does, for a scene whose physics
    is ``"mujoco"``); ``trace()`` returns what it drew as a ``PenTrace``-shaped triple.

    Args:
        model: the arm (its gripper's tool).  tip: the arm with the pen's tip as its tool.
        sheet: the paper.  scene: the table and the arm's base (its objects are bodies too).
        pen_length: how much of the pen stands out of the hand [m].  arm: the arm's name.
    """

    def __init__(
        self,
        model: ArmModel,
        tip: ArmModel,
        sheet: Sheet,
        scene: Scene,
        pen_length: float,
        arm: str | None = None,
    ) -> None:
        self.model, self.sheet, self.scene, self.arm = model, sheet, scene, arm
        q0 = np.zeros(model.dof)
        self.T_tool_tip: F64 = np.linalg.inv(fk(model, q0)) @ fk(tip, q0)
        self.pen_length = pen_length
        self.holding = False
        self.engine: Engine | None = None
        self._pen = -1  # the pen's geom
        self._jaws: NDArray[np.intp] = np.zeros(0, dtype=np.intp)  # the jaws' geoms
        self._jaw_types: NDArray[np.int32] = np.zeros(0, dtype=np.int32)  # their conaffinity
        self._table = -1
        self._t: list[float] = []
        self._p: list[F64] = []
        self._down: list[bool] = []

    def _add_pen(self, spec: Any) -> None:
        from ._engine import mujoco_module

        capsule = mujoco_module().mjtGeom.mjGEOM_CAPSULE
        tip = self.T_tool_tip[:3, 3]  # in the tool's frame, the pen along its approach (x)
        approach = np.array([1.0, 0.0, 0.0])
        site = spec.site("tool")
        rot = _quat_matrix(np.array(site.quat, dtype=np.float64))  # the site in its body
        end = np.array(site.pos, dtype=np.float64) + rot @ (tip - PEN_RADIUS * approach)
        back = end - rot @ approach * self.pen_length
        site.parent.add_geom(
            name="pen", type=capsule, fromto=[*back, *end], size=[PEN_RADIUS, 0.0, 0.0],
            contype=PEN_CONTYPE, conaffinity=1, margin=INK, gap=INK,
            priority=1, friction=[PEN_FRICTION, 0.005, 0.0001],
        )  # fmt: skip

    def on_step(self, world: Any, t: float) -> None:
        """One MuJoCo step; the tip and whether the pen touches the paper."""
        sim = world.arm(self.arm)
        self._advance(sim, sim.q(), t, float(getattr(world, "dt", 1e-3)))

    def on_steps(self, world: Any, times: F64) -> None:
        """A stretch of steps: one MuJoCo step for each recorded step."""
        sim = world.arm(self.arm)
        dt = float(getattr(world, "dt", 1e-3))
        for q, t in zip(sim.recent(len(times)), times, strict=True):
            self._advance(sim, q, float(t), dt)

    def may_skip(self) -> bool:
        """The world may skip still steps unless the pen is held (it may be pressing)."""
        return not self.holding

    def _advance(self, sim: Any, q: F64, t: float, dt: float) -> None:
        engine = self.engine
        if engine is None:
            engine = self.engine = Engine(sim.model, self.scene, dt, edit=self._add_pen)
            engine.place(q, sim.grip(), {c.name: c.T for c in self.scene.cubes})
            self._pen = int(engine.m.geom("pen").id)
            engine.m.geom_friction[self._pen, 0] = PEN_FRICTION  # the engine set every geom's
            self._table = int(engine.m.geom("table").id)
            bodies = engine.at.jaw_bodies
            self._jaws = np.flatnonzero(np.isin(engine.m.geom_bodyid, bodies))
            self._jaw_types = np.array(engine.m.geom_conaffinity[self._jaws])
        m = engine.m
        m.geom_contype[self._pen] = PEN_CONTYPE if self.holding else 0
        m.geom_conaffinity[self._jaws] = 0 if self.holding else self._jaw_types
        engine.step(q, sim.grip() if sim.model.gripper.present else None)
        if not self.holding:
            return
        T = engine.tool_pose() @ self.T_tool_tip
        self._t.append(t)
        self._p.append(T[:3, 3].copy())
        self._down.append(self._touching(engine))

    def _touching(self, engine: Engine) -> bool:
        d = engine.d
        if d.ncon == 0:
            return False
        pairs = d.contact.geom[: d.ncon]
        return bool(np.any((pairs == self._pen).any(axis=1) & (pairs == self._table).any(axis=1)))

    def recorded(self) -> tuple[F64, F64, NDArray[np.bool_]] | None:
        """Times [s] (N,), tips [m] (N, 3) in the scene frame, and down (N,): the pen on
        the table inside the sheet; None if nothing was recorded."""
        if not self._t:
            return None
        p = np.array(self._p)
        sheet = self.sheet
        inside = sheet.contains((p - sheet.origin) @ np.column_stack([sheet.u, sheet.v]))
        return np.array(self._t), p, np.array(self._down) & inside


def _quat_matrix(q: F64) -> F64:
    w, x, y, z = q / np.linalg.norm(q)
    return np.array(
        [
            [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
            [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
            [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
        ]
    )
