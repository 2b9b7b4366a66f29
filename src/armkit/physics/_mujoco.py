"""The scene's objects moved by MuJoCo instead of armkit's rules: ``MujocoPhysics``.

An Observer of the World, as ``armkit.scene.ScenePhysics`` is, and read the same way
(``scene`` the objects at rest with a held cube left out, ``holding``, ``events``,
``cube(name)``), so every task, check and view works on it unchanged. Each World
step is one MuJoCo step: the arm's actuators follow the simulated servos' true angles
(the drivers and the simulated devices are the same as without MuJoCo), the jaws
follow the simulated gripper until something stops them, and then the gripper servo
is stopped where MuJoCo's jaws are (``grip_stop``), so the driver reads where the
cube stopped them. What happens is told as the rules tell it:

- ``grasped``: the jaws stopped with both pads on one cube;
- ``missed``: the jaws closed past a nearby cube's size without stopping on it, or
  stopped on something else;
- ``dropped``: a held cube slipped out of the grip (more than ``SLIP`` from where the
  jaws took it), or a released cube fell more than 5 mm;
- ``placed`` / ``tipped``: a released (or pushed) cube came to rest upright within
  ``FLAT_TILT`` of a face, or not.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ..scene import (
    DROP_HEIGHT,
    FLAT_TILT,
    Cube,
    Held,
    Scene,
    ScenePhysics,
    support_under,
    yaw_and_face,
)
from ._engine import FRICTION, Engine

F64 = NDArray[np.float64]
BLOCKED = 0.5e-3  # [m]: MuJoCo's jaws this much wider than the gripper servo = stopped
PAST = 2e-3  # [m]: jaws this much narrower than a cube have closed past it (not squeezing it)
SQUEEZE = 2e-3  # [m]: a restored grip's jaws are driven this much inside the cube
SETTLED = 0.05e-3  # [m]: jaws moving less than this between looks have closed on it
SLIP = 3e-3  # [m]: a held cube this far from where the jaws took it has slipped
MOVED = 1e-3  # [m]: a cube at rest pushed this far is moving
REST_SPEED = 2e-3  # [m/s]: a cube slower than this (``Engine.cube_speed``) is still
REST_CHECKS = 5  # looks in a row at rest = come to rest
EVERY = 10  # steps between looks at the cubes (slips, settling)
SHOWN_CONTACTS = 64  # contact points a view is given, at most
NEAR = 0.06  # [m]: a closing this close to a cube that misses it is reported


@dataclass(frozen=True)
class GripSample:
    """A held cube as the jaws hold it, every ``EVERY`` steps once they have closed on it.

    Attributes:
        t: simulated time [s].  cube: its name.
        force: the gripper actuator's force on its jaws [N].
        slip: how far the cube has moved in the grip since the jaws closed on it [m].
    """

    t: float
    cube: str
    force: float
    slip: float


class MujocoPhysics(ScenePhysics):
    """Attach with ``world.attach(MujocoPhysics(scene))`` (``tasks.attach_scene`` does,
    for a scene whose ``physics`` is ``"mujoco"``). The MuJoCo model is built on the
    first step, from the arm and the cubes where they are then. ``grips`` records the
    held cubes' grip force and slip (``GripSample``) every 10 steps.

    Args:
        scene: the objects at rest.  arm: the arm's name in the World (None: the only one).
        friction: the pads' and cubes' sliding friction coefficient.
    """

    def __init__(self, scene: Scene, arm: str | None = None, friction: float = FRICTION) -> None:
        from ._engine import mujoco_module

        mujoco_module()  # refused here, before anything moves, if MuJoCo is missing
        super().__init__(scene, arm)
        self.friction = friction
        self.engine: Engine | None = None
        self._sizes = {c.name: c for c in scene.cubes}
        self._stopped: float | None = None  # the opening MuJoCo's jaws stopped at [m]
        self._moving: dict[
            str, tuple[float, int]
        ] = {}  # cube -> (bottom when let go [m], still looks)
        self._steps = 0
        self._missed_once = False
        self._last_width: float | None = None  # the gripper servo's goal at the last step [m]
        self._looked_width = -1.0  # the jaws' opening at the last look [m]
        self.grips: list[GripSample] = []  # the held cubes' grip force and slip, as held
        self._pushed: set[str] = set()  # moving cubes that were standing, not let go
        self._in_hand: F64 | None = None  # the held cube in MuJoCo's tool frame, once squeezed

    def restore(self, cube: Cube, T_tool_object: F64) -> None:
        """Start with ``cube`` in the gripper at ``T_tool_object`` (4, 4) [m] (kept state)."""
        self._sizes[cube.name] = cube
        self.holding = Held(cube, np.asarray(T_tool_object, dtype=np.float64))
        self.scene = self.scene.without_cube(cube.name)

    def may_skip(self) -> bool:
        """The world may skip steps while nothing moves here either."""
        engine = self.engine
        return engine is not None and not self._moving and engine.arm_speed() < 1e-4

    def on_step(self, world: Any, t: float) -> None:
        """One MuJoCo step with the arm where its servos are; then grasp, slip or settle."""
        sim = world.arm(self._arm)
        self._advance(sim, sim.q(), t, float(getattr(world, "dt", 1e-3)))

    def on_steps(self, world: Any, times: F64) -> None:
        """A stretch of World steps at ``times`` [s] (the jaws still in it): one MuJoCo
        step for each, the arm's actuators at the angles each step recorded."""
        sim = world.arm(self._arm)
        dt = float(getattr(world, "dt", 1e-3))
        for q, t in zip(sim.recent(len(times)), times, strict=True):
            self._advance(sim, q, float(t), dt)

    def _advance(self, sim: Any, q: F64, t: float, dt: float) -> None:
        self._model = sim.model
        width = sim.grip()
        engine = self.engine
        if engine is None:
            engine = self.engine = self._build(sim, q, width, dt)
        goal = float(getattr(getattr(sim, "body", None), "grip_goal", width))
        jaws = width if self._stopped is None else min(goal, self._stopped - SQUEEZE)
        engine.step(q, jaws if sim.model.gripper.present else None)
        self._q = q
        self._steps += 1
        if sim.model.gripper.present:
            self._grip(sim, engine, width, goal, t)
        if self._steps % EVERY == 0:
            self._look(sim, engine, t)

    def cube(self, name: str) -> Cube:
        """The cube ``name`` where MuJoCo has it now (snapped to its nearest face up)."""
        engine = self.engine
        if engine is None or name not in engine.at.cubes:
            return super().cube(name)
        return self._sizes[name].moved(engine.cube_pose(name))

    def pose(self, name: str) -> F64:
        """The cube ``name``'s centre pose as MuJoCo has it, tilt and all (4, 4) [m]."""
        engine = self.engine
        if engine is None or name not in engine.at.cubes:
            return super().pose(name)
        return engine.cube_pose(name)

    def contacts(self) -> F64:
        """Where MuJoCo's bodies touch now (at most ``SHOWN_CONTACTS``), scene frame [m],
        shape (n, 3): what ``armkit view --contacts`` draws."""
        engine = self.engine
        if engine is None:
            return np.zeros((0, 3))
        d = engine.d
        found: F64 = np.array(d.contact.pos[: min(d.ncon, SHOWN_CONTACTS)], dtype=np.float64)
        return found.reshape(-1, 3)

    # -- building -----------------------------------------------------------------
    def _build(self, sim: Any, q: F64, width: float, dt: float) -> Engine:
        held = self.holding
        everything = (
            self.scene
            if held is None
            else replace(self.scene, cubes=(*self.scene.cubes, held.cube))
        )
        engine = Engine(sim.model, everything, dt, self.friction)
        poses = {c.name: c.T for c in self.scene.cubes}
        if held is not None:
            poses[held.cube.name] = self._tool(sim.model, q, held.cube.size) @ held.T_tool_object
            self._stopped = held.cube.size
            sim.grip_stop(held.cube.size)
            width = held.cube.size
        engine.place(q, width, poses)
        return engine

    # -- the jaws -------------------------------------------------------------------
    def _grip(self, sim: Any, engine: Engine, width: float, goal: float, t: float) -> None:
        opening = engine.opening()
        last, self._last_width = self._last_width, goal
        if last is not None and goal > last:
            self._missed_once = False
        closing = last is not None and goal <= last and goal < opening - BLOCKED
        if self._stopped is None:
            if closing and width < opening - BLOCKED and self.holding is None:
                self._stopped_on(sim, engine, opening, t)
            if closing and self._stopped is None and self.holding is None:
                self._closing_past(sim, engine, opening, t)
            return
        if goal > self._stopped + BLOCKED:  # opening again: the servo lets go
            self._stopped = self._in_hand = None
            sim.grip_stop(None)
            self._let_go(engine)
        elif opening < self._stopped - BLOCKED:  # the jaws squeeze in: the servo follows
            self._stopped = opening
            sim.grip_stop(min(opening, width))

    def _stopped_on(self, sim: Any, engine: Engine, opening: float, t: float) -> None:
        """The jaws lag the gripper servo: if both pads are on one cube it is grasped
        (the servo stops where MuJoCo's jaws are); else they are only slowed."""
        left, right = engine.touching()
        both = sorted(left & right)
        if len(both) != 1:
            return
        name = both[0]
        self._stopped = opening
        sim.grip_stop(min(opening, sim.grip()))  # where the servo is, if it ran ahead
        T_tool = self._tool(sim.model, self._q_now(sim), opening)
        T_tool_object = np.linalg.inv(T_tool) @ engine.cube_pose(name)
        self.holding = Held(self._rest(name), T_tool_object)
        self.scene = self.scene.without_cube(name)
        self._moving.pop(name, None)
        self._add(t, "grasped", name, f"grasped {name}", T_tool_object[:3, 3])

    def _closing_past(self, sim: Any, engine: Engine, width: float, t: float) -> None:
        """The jaws closed below the size of the nearest cube without stopping: a miss."""
        if self._missed_once:
            return
        near = self._nearest(sim, engine)
        if near is None or width > self._sizes[near].size - PAST:
            return
        left, right = engine.touching()
        if near in left | right:  # pressed into it, not past it
            return
        self._missed_once = True
        T_tool = self._tool(sim.model, self._q_now(sim), width)
        off = np.linalg.inv(T_tool) @ engine.cube_pose(near)
        gap = float(np.linalg.norm(off[:3, 3])) * 1000.0
        self._add(
            t, "missed", near,
            f"missed {near}: the jaws closed beside it (its centre {gap:.1f} mm from the tool point)",
            off[:3, 3],
        )  # fmt: skip

    def _let_go(self, engine: Engine) -> None:
        held, self.holding = self.holding, None
        if held is None:
            return
        name = held.cube.name
        bottom = float(engine.cube_pose(name)[2, 3]) - held.cube.size / 2.0
        self._moving[name] = (bottom, 0)
        self.scene = replace(self.scene, cubes=(*self.scene.cubes, self.cube(name)))

    def _slipped(self, sim: Any, engine: Engine, t: float, how: str) -> None:
        held = self.holding
        assert held is not None
        self._stopped = self._in_hand = None
        sim.grip_stop(None)
        self._let_go(engine)
        self._add(t, "dropped", held.cube.name, f"dropped {held.cube.name}: it {how}")

    # -- the cubes ------------------------------------------------------------------
    def _look(self, sim: Any, engine: Engine, t: float) -> None:
        held = self.holding
        if held is not None:
            name = held.cube.name
            in_hand = np.linalg.inv(engine.tool_pose()) @ engine.cube_pose(name)
            width = engine.opening()
            if abs(width - self._looked_width) > SETTLED or self._in_hand is None:
                self._looked_width, self._in_hand = width, in_hand  # still squeezing it
            else:
                off = float(np.linalg.norm(in_hand[:3, 3] - self._in_hand[:3, 3]))
                self.grips.append(GripSample(t, name, engine.jaw_force(), off))
                if off > SLIP:
                    self._slipped(sim, engine, t, f"slipped {off * 1000:.1f} mm in the grip")
        for cube in self.scene.cubes:
            if cube.name not in self._moving:
                now = engine.cube_pose(cube.name)[:3, 3]
                if float(np.linalg.norm(now - cube.center)) > MOVED:
                    self._moving[cube.name] = (float(cube.position[2]), 0)
                    self._pushed.add(cube.name)
        for name, (bottom, still) in list(self._moving.items()):
            still = still + 1 if engine.cube_speed(name) < REST_SPEED else 0
            self._moving[name] = (bottom, still)
            if still >= REST_CHECKS:
                del self._moving[name]
                self._settled(engine, name, bottom, t, name in self._pushed)
                self._pushed.discard(name)
            else:
                self.scene = self.scene.with_cube(self.cube(name))

    def _settled(self, engine: Engine, name: str, bottom: float, t: float, pushed: bool) -> None:
        T = engine.cube_pose(name)
        cube = self._sizes[name].moved(T)
        others = self.scene.without_cube(name)
        _, _, tilt = yaw_and_face(T[:3, :3])
        below = support_under(others, cube.footprint(), float(T[2, 3]))  # under its centre
        fall = bottom - float(cube.position[2])
        self.scene = replace(others, cubes=(*others.cubes, cube))
        if pushed and tilt <= FLAT_TILT and fall <= DROP_HEIGHT:
            return  # nudged where it stands: nothing to tell
        if tilt > FLAT_TILT:
            self._add(t, "tipped", name, f"tipped {name} on {below.on}: it rests "
                      f"{math.degrees(tilt):.0f} deg off upright")  # fmt: skip
        elif fall > DROP_HEIGHT:
            self._add(
                t, "dropped", name, f"dropped {name} on {below.on}, fell {fall * 1000:.1f} mm"
            )
        else:
            self._add(t, "placed", name, f"placed {name} on {below.on}")

    def _nearest(self, sim: Any, engine: Engine) -> str | None:
        """The cube nearest the tool point within ``NEAR``, not held; None if none."""
        T_tool = self._tool(sim.model, self._q_now(sim), engine.opening())
        best, found = NEAR, None
        for cube in self.scene.cubes:
            gap = float(np.linalg.norm(engine.cube_pose(cube.name)[:3, 3] - T_tool[:3, 3]))
            if gap < best:
                best, found = gap, cube.name
        return found

    def _rest(self, name: str) -> Cube:
        try:
            return self.scene.cube(name)
        except ValueError:
            return self._sizes[name]

    def _q_now(self, sim: Any) -> F64:
        q: F64 = sim.q()
        return q
