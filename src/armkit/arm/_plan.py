"""A plan: a motion worked out whole from a ``Start`` (every pose solved and checked,
every step timed by the driver's own forecast) before anything moves; ``Arm.run``
carries it out."""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np
from numpy.typing import NDArray

from .._terminal import count
from ..model import ArmModel
from ..motion import JointPath, Streamer
from ..scene import Cube, Held, Scene
from ._start import Start

F64 = NDArray[np.float64]


@dataclass(frozen=True)
class Step:
    """One step of a plan: a joint move (``q``), a path (``path``, ``q`` its end) or a
    gripper command (``grip``).

    Attributes:
        label: what it is for people (``"pick red: down 2/3"``).
        q: joint angles to move to [rad], shape (dof,), or None for a gripper step.
        grip: gripper opening to command [m], or None for a move.
        point: the tool point the move goes to, in the scene frame [m], (3,), or None.
        pitch: the tool's pitch there [rad], or None.
        holding: the cube in the gripper during the step, or None.
        path: a path followed from its start (a move onto it first) by ``streamer``
            (None: waypoint by waypoint, each waited for), or None; ``kin``: the model
            it was solved with (its tool point: the jaws', a pen's tip, ...).
        speed: fraction of every joint's max velocity (None: 1).  duration: the move's
            time [s] (None: as fast as allowed).
        at: start the step this long after the plan began [s], a move going on without
            waiting (a piece's strikes), or None: when the step before has ended.
        settle: wait for the arm to stand still before and after a gripper command.
        motor: a timed motor run (joint, direction +1/-1, seconds [s]), or None.
        light: the light switched on (True) or off (False), or None.
        A step with none of ``q``, ``grip``, ``motor``, ``light`` waits ``seconds``.
        seconds: how long the step takes, by the driver's forecast [s].
    """

    label: str
    q: F64 | None = None
    grip: float | None = None
    point: F64 | None = None
    pitch: float | None = None
    holding: str | None = None
    path: JointPath | None = None
    streamer: Streamer | None = None
    kin: ArmModel | None = None
    speed: float | None = None
    duration: float | None = None
    at: float | None = None
    settle: bool = False
    motor: tuple[str, int, float] | None = None
    light: bool | None = None
    seconds: float = 0.0


@dataclass(frozen=True)
class Plan:
    """A motion planned whole: its steps from ``start``, and ``end``, where it leaves
    the arm (its joints as the driver will read them, grip, held cube, the objects at
    rest, battery): the Start of whatever comes next.

    Attributes:
        task: what it is (``"move"``, ``"pick red"``).
        after: every object where the plan leaves it, a held cube where the gripper holds
            it (a task's expectation), or None: ``end.scene``.
        planning_time: how long planning took [s].
    """

    task: str
    start: Start
    steps: tuple[Step, ...]
    end: Start
    after: Scene | None = None
    planning_time: float = 0.0

    @property
    def arm(self) -> str:
        """The arm's model name."""
        return self.start.model.name

    @property
    def q_start(self) -> F64:
        """The arm's joints at the start [rad], shape (dof,)."""
        return self.start.q

    @property
    def q_end(self) -> F64:
        """The arm's joints at the end of the plan [rad], shape (dof,)."""
        return self.end.q.copy()

    @property
    def held(self) -> Held | None:
        """The cube in the gripper at the end, with its pose in the tool frame, or None."""
        return self.end.held

    @property
    def seconds(self) -> float:
        """How long carrying it out takes [s], by the driver's forecasts."""
        return float(sum(s.seconds for s in self.steps))

    @property
    def before(self) -> Scene | None:
        """The scene it starts with, a held cube where it was picked from."""
        return with_held(self.start.scene, self.start.held)

    @property
    def rest(self) -> Scene | None:
        """The scene the next task plans with (as ``armkit.scene.rest_scene`` gives a
        simulated one): the objects at rest, a cube still held where it was picked from."""
        return with_held(self.end.scene, self.end.held)

    @property
    def moves(self) -> int:
        """Number of joint moves and paths."""
        return sum(1 for s in self.steps if s.q is not None)

    def then(self, other: Plan, task: str | None = None) -> Plan:
        """This plan followed by ``other`` (planned from this one's ``end``)."""
        return Plan(
            task or self.task, self.start, self.steps + other.steps, other.end,
            other.after, self.planning_time + other.planning_time,
        )  # fmt: skip

    def lines(self) -> list[str]:
        """The plan as text: one line per step, then the cubes that move."""
        scene = "" if self.before is None else f", scene {self.before.name}"
        head = (
            f"{self.task} ({self.arm}{scene}): {count(len(self.steps), 'step')}, "
            f"{count(self.moves, 'move')}, planned in {self.planning_time * 1000:.1f} ms"
        )
        out = [head]
        for k, step in enumerate(self.steps, 1):
            out.append(f"{k:3d}  {step_text(step)}")
        if self.before is not None and self.after is not None:
            moved = [c for c in self.after.cubes if _moved(self.before, c)]
            out += [f"  expected: {cube_text(cube)}" for cube in moved]
        return out

    def __str__(self) -> str:
        return "\n".join(self.lines())


def with_held(scene: Scene | None, held: Held | None) -> Scene | None:
    """``scene`` with the ``held`` cube where it was picked from (as it is if none)."""
    if scene is None or held is None or held.cube.name in {c.name for c in scene.cubes}:
        return scene
    return replace(scene, cubes=(*scene.cubes, held.cube))


def step_text(step: Step) -> str:
    """One step for people: its label, then the gripper's opening or the pose [mm, deg]."""
    if step.grip is not None:
        return f"{step.label:<40s} gripper {step.grip * 1000:.1f} mm"
    joints = "" if step.q is None else " ".join(f"{math.degrees(a):7.2f}" for a in step.q)
    if step.point is None or step.pitch is None:
        return f"{step.label:<40s} [{joints}] deg"
    x, y, z = (float(v) * 1000 for v in step.point)
    pitch = math.degrees(step.pitch)
    return f"{step.label:<40s} ({x:6.1f}, {y:6.1f}, {z:6.1f}) mm pitch {pitch:5.1f}  [{joints}] deg"


def cube_text(cube: Cube) -> str:
    """``red at (220.0, -45.0, 3.0) mm, yaw 0.0 deg, +x up``."""
    x, y, z = (float(v) * 1000 for v in cube.position)
    return f"{cube.name} at ({x:.1f}, {y:.1f}, {z:.1f}) mm, yaw {round(math.degrees(cube.yaw), 1) + 0.0:.1f} deg, {cube.up_face} up"


def _moved(before: Scene, cube: Cube) -> bool:
    old = {c.name: c for c in before.cubes}.get(cube.name)
    if old is None:
        return True
    R_old, R_new = old.T[:3, :3], cube.T[:3, :3]
    turned = float(np.linalg.norm(R_old - R_new)) > 1e-6
    return turned or float(np.linalg.norm(old.position - cube.position)) > 1e-6
