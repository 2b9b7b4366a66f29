"""Listening under MuJoCo: ``MujocoListener``, the ``Listener`` of a scene whose physics
is ``"mujoco"``. The mallet's head is a small sphere on the hand, the bars boxes and
the drum heads discs where the scene puts them (``surfaces``); the arm follows the
simulated servos as under ``armkit.physics.MujocoPhysics``. A strike is MuJoCo's
contact between the head and a surface beginning (its time moved back by how deep
the head already is over its speed), the dwell how long the contact lasts; a surface
sounds again only after the head has risen ``REARM`` above the lowest it went on it, as the
rules' listener has it: a head chattering on the bar is one strike."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ..kinematics import fk
from ..model import ArmModel
from ..physics import Engine, mujoco_module
from ..scene import Scene
from ._layout import Instrument
from ._listen import REARM, Surface, surfaces
from ._onsets import Contact

F64 = NDArray[np.float64]
HEAD = 0.002  # [m] the head's radius: its lowest point is the mallet model's tool point
BODY = 0.005  # [m] half the thickness of a bar or drum head as a body


class MujocoListener:
    """Observer recording every strike of one simulated arm, as MuJoCo has them.

    Args:
        model: the arm with its gripper.  mallet: the arm with the mallet's head as its tool.
        layout: the scene's instruments.  scene: the table and the arm's base.
        arm: the simulated arm's name in the world (None: the only one).
    """

    def __init__(
        self,
        model: ArmModel,
        mallet: ArmModel,
        layout: Sequence[Instrument],
        scene: Scene,
        arm: str | None = None,
    ) -> None:
        self.model, self.scene, self.arm = model, scene, arm
        q0 = np.zeros(model.dof)
        self.T_tool_head: F64 = np.linalg.inv(fk(model, q0)) @ fk(mallet, q0)
        self.surfaces = surfaces(layout)
        self.contacts: list[Contact] = []
        self.dwell: list[float] = []
        self.engine: Engine | None = None
        self._head = -1
        self._geoms: dict[int, Surface] = {}
        self._on: tuple[int, float, float] | None = None  # surface, since [s], lowest head [m]
        self._last: tuple[float, F64] | None = None

    def _add(self, spec: Any) -> None:
        mj = mujoco_module()
        site = spec.site("tool")
        head = self.T_tool_head[:3, 3] - HEAD * self.T_tool_head[:3, 2]  # above the tip
        R = np.zeros(9)
        mj.mju_quat2Mat(R, np.array(site.quat, dtype=np.float64))
        at = np.array(site.pos, dtype=np.float64) + R.reshape(3, 3) @ head
        site.parent.add_geom(
            name="mallet", type=mj.mjtGeom.mjGEOM_SPHERE, pos=at, size=[HEAD, 0, 0],
            contype=4, conaffinity=1,
        )  # fmt: skip
        for k, s in enumerate(self.surfaces):
            centre = s.centre - np.array([0.0, 0.0, BODY])
            if s.drum:
                spec.worldbody.add_geom(
                    name=f"surface_{k}", type=mj.mjtGeom.mjGEOM_CYLINDER, pos=centre,
                    size=[s.half[0], BODY, 0.0],
                )  # fmt: skip
                continue
            angle = float(np.arctan2(s.along[1], s.along[0]))
            spec.worldbody.add_geom(
                name=f"surface_{k}", type=mj.mjtGeom.mjGEOM_BOX, pos=centre,
                quat=[np.cos(angle / 2), 0.0, 0.0, np.sin(angle / 2)],
                size=[s.half[0], s.half[1], BODY],
            )  # fmt: skip

    def on_step(self, world: Any, t: float) -> None:
        """One MuJoCo step with the arm where its servos are; a strike if one began."""
        sim = world.arm(self.arm)
        engine = self.engine
        if engine is None:
            engine = self.engine = Engine(
                sim.model, self.scene, float(getattr(world, "dt", 1e-3)), edit=self._add
            )
            engine.place(sim.q(), sim.grip(), {})
            self._head = int(engine.m.geom("mallet").id)
            self._geoms = {
                int(engine.m.geom(f"surface_{k}").id): s for k, s in enumerate(self.surfaces)
            }
        engine.step(sim.q(), sim.grip() if sim.model.gripper.present else None)
        tip = (engine.tool_pose() @ self.T_tool_head)[:3, 3]
        last, self._last = self._last, (t, tip)
        touched = self._touched(engine)
        if self._on is not None:
            geom, since, low = self._on
            if touched is not None and touched[0] == geom:
                self.dwell[-1] = t - since  # still on it
                self._on = (geom, since, min(low, float(tip[2])))
            elif tip[2] > low + REARM:
                self._on = None  # risen off it: it may sound again
            return
        if touched is None or last is None:
            return
        geom, depth = touched
        speed = float(np.linalg.norm(tip - last[1])) / max(t - last[0], 1e-9)
        when = t - (depth / speed if speed > 1e-6 else 0.0)
        s = self._geoms[geom]
        self.contacts.append(Contact(max(when, last[0]), s.instrument, s.note, speed, s.drum))
        self.dwell.append(0.0)
        self._on = (geom, when, float(tip[2]))

    def _touched(self, engine: Engine) -> tuple[int, float] | None:
        """The surface the head touches now and how deep [m], or None."""
        d = engine.d
        for k in range(d.ncon):
            a, b = (int(g) for g in d.contact.geom[k])
            other = b if a == self._head else a if b == self._head else -1
            if other in self._geoms:
                return other, max(0.0, -float(d.contact.dist[k]))
        return None
