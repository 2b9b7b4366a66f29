"""``Arm``: a model and a driver in one object, in millimetres and degrees.

Every motion is planned first (``plan_move_to``, ``plan_grip``, ...: a ``Plan`` from a
``Start``, checked and timed whole; the conversion to SI happens here, once) and then
carried out by ``run``, the only way a command reaches the driver. A refused motion
moves nothing.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence
from pathlib import Path
from types import TracebackType
from typing import Any, NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._arm_inputs import number, numbers, pitch_radians, timing_of
from .._closing import close_after
from .._errors import InputError
from ..connect import SimArm, World, open_driver, world_of
from ..drivers import Driver
from ..kinematics import fk, ik, pitch_follows, pitch_of
from ..model import ArmModel, load_model
from ..motion import JointPath, Streamer, TimedStreaming, approach, clock_of, retreat
from ..scene import Held, HeldTool, Scene, load_scene
from ._carry import Say, carry_out, check_start
from ._plan import Plan
from ._planner import (
    inside,
    plan_follow,
    plan_grip,
    plan_joints,
    plan_lift_out,
    plan_light,
    plan_motor_run,
    plan_through,
)
from ._start import Start

F64 = NDArray[np.float64]
GRIP_S = 0.5  # [s] time given to a real arm to stand still around a gripper command
SETTLE_MAX_S = 5.0  # [s] the longest wait for a simulated arm to come to rest


class Position(NamedTuple):
    """Where the gripper is: x, y, z [mm] in the world frame, pitch [deg]."""

    x: float
    y: float
    z: float
    pitch: float


class Arm:
    """Drive an arm by where the gripper should go (mm, degrees). Every numeric argument
    must be a number (an int, a float or a numpy one; not True or False, not text such as
    ``"20"``): InputError naming the argument and its unit otherwise, before anything moves.

    Every motion has a ``plan_*`` twin that plans it from a ``Start`` (default: the arm
    as it is now, ``start()``) and returns the ``Plan`` without moving; ``run(plan)``
    carries a plan out.

    Args:
        model: a shipped arm name, a model file path, or an ``ArmModel``.
        driver: a driver name (``"sim"``, ``"ssc32"``, ...) or an open ``Driver``.
        port: the driver's port (see ``armkit.connect.open_driver``).
        world: the simulation world to put a simulated arm in (None: a new one).
        scene: what is on the table: a ``Scene`` or a scene name or file (loaded with
            ``armkit.scene.load_scene``); every move is checked against it, and against
            the table plane even without one.

    Attributes ``scene`` and ``held`` (a ``scene.Held``: the cube in the gripper and its
    pose in the tool frame, checked with the links; the tasks and the script runner
    set it) may be changed between moves.
    """

    def __init__(
        self,
        model: str | Path | ArmModel = "openmanipulator_x",
        driver: str | Driver = "sim",
        port: str | None = None,
        *,
        world: World | None = None,
        scene: Scene | str | Path | None = None,
    ) -> None:
        if not isinstance(driver, str | Driver):
            raise InputError(
                f"driver must be a driver name ('sim', 'ssc32', ...; armkit.drivers."
                f"driver_names()) or an open Driver, got {driver!r}"
            )
        if scene is not None and not isinstance(scene, Scene | str | Path):
            raise InputError(
                "scene must be a Scene, a scene name or file (armkit.scene.load_scene) or "
                f"None, got {type(scene).__name__}"
            )
        self.model = model if isinstance(model, ArmModel) else load_model(model)
        self.scene = load_scene(scene) if isinstance(scene, str | Path) else scene
        if isinstance(driver, str):
            self.driver = open_driver(self.model, driver, port, world=world)
        else:
            self.driver = driver
        self.clock = clock_of(self.driver)
        self.held: Held | None = None  # a cube in the gripper: checked with the links
        self._opening: float | None = None  # the jaws' opening [m], once set
        self._limp = False  # relaxed: the next move holds again first
        self._tool: HeldTool | None = None  # a pen or mallet held, on real hardware

    @property
    def world(self) -> World | None:
        """The simulation world this arm moves in (its true state, recording, observers);
        None on real hardware."""
        return world_of(self.driver)

    @property
    def sim(self) -> SimArm | None:
        """The simulated arm behind this one (its truth: joints, gripper, at rest), or None
        on real hardware."""
        world = self.world
        if world is None:
            return None
        return next((a for a in world.arms() if a.model.name == self.model.name), None)

    def start(self) -> Start:
        """The arm as it is now, as a plan starts from it: its joints as the driver reads
        them, its grip, the cube it holds, its scene, and its driver's forecasts."""
        sim = self.sim
        jaws = sim.grip() if self._opening is None and sim is not None else None
        return Start(
            self.model, self.read(), self._opening, self.held, self.scene, jaws,
            self.motor_s(), self.driver, self.tool,
        )  # fmt: skip

    @property
    def tool(self) -> HeldTool | None:
        """The tool in the gripper (a pen, a mallet; its tip is then the tool point every
        move is planned with), or None. A simulated arm keeps it with its joints."""
        sim = self.sim
        return sim.tool if sim is not None else self._tool

    def hold_tool(self, tool: HeldTool | None) -> None:
        """The gripper now holds ``tool`` (a job that picks a pen or takes the mallet
        says so), or nothing (None); a simulated gripper's jaws stop on it."""
        if tool is not None and not isinstance(tool, HeldTool):
            raise InputError(f"tool must be a scene.HeldTool or None, got {tool!r}")
        sim = self.sim
        if sim is not None:
            sim.hold_tool(tool)
        self._tool = tool

    def plan_move_to(
        self,
        x: float,
        y: float,
        z: float,
        pitch: float | None = None,
        *,
        speed: float | None = None,
        duration: float | None = None,
        start: Start | None = None,
    ) -> Plan:
        """``move_to``'s plan from ``start`` (None: the arm now); nothing moves."""
        timing = timing_of(speed, duration, True, None)  # checked before solving
        target = numbers([x, y, z], "x, y, z [mm]") / 1000.0
        at = start or self.start()
        q = ik(at.kin, target, pitch_radians(pitch), at.q).q
        return plan_joints(at, q, speed=timing.speed, duration=timing.duration)

    def move_to(
        self,
        x: float,
        y: float,
        z: float,
        pitch: float | None = None,
        *,
        speed: float | None = None,
        duration: float | None = None,
        wait: bool = True,
        timeout: float | None = None,
    ) -> None:
        """Move the gripper point to (x, y, z) [mm], approach ``pitch`` [deg] above the
        horizontal, -180..180 (-90: pointing straight down; None: the model's default,
        else any), by a joint move.

        Args:
            speed: fraction of every joint's max velocity, (0, 1]; None = 1.
            duration: time for the move [s]; None = as fast as allowed.
            wait: block until the arm is there.  timeout: give up after [s] (DeviceError).
        Raises:
            InputError: a value that is not a number (text such as ``"200"`` included),
                or a pitch outside -180..180; nothing moves.
            UnreachableError: the point (and pitch) is out of reach or the joint limits.
        """
        timing = timing_of(speed, duration, wait, timeout)
        plan = self.plan_move_to(x, y, z, pitch, speed=timing.speed, duration=timing.duration)
        self.run(plan, wait=timing.wait, timeout=timing.timeout)

    def plan_move_joints(
        self,
        angles: Mapping[str, float] | Sequence[float],
        *,
        speed: float | None = None,
        duration: float | None = None,
        start: Start | None = None,
    ) -> Plan:
        """``move_joints``'s plan from ``start`` (None: the arm now); nothing moves."""
        timing = timing_of(speed, duration, True, None)
        at = start or self.start()
        q = self._joint_target(angles, at.q)
        return plan_joints(at, q, speed=timing.speed, duration=timing.duration)

    def move_joints(
        self,
        angles: Mapping[str, float] | Sequence[float],
        *,
        speed: float | None = None,
        duration: float | None = None,
        wait: bool = True,
        timeout: float | None = None,
    ) -> None:
        """Move joints to ``angles`` [deg]: one per joint in order, or a dict by name
        (joints not named stay where they are). Options as ``move_to``."""
        timing = timing_of(speed, duration, wait, timeout)
        plan = self.plan_move_joints(angles, speed=timing.speed, duration=timing.duration)
        self.run(plan, wait=timing.wait, timeout=timing.timeout)

    def turn_to(self, joint: str, deg: float, *, speed: float | None = None) -> None:
        """Turn one joint to ``deg`` [deg]; the others stay."""
        self.move_joints({joint: deg}, speed=speed)

    def turn_by(self, joint: str, deg: float, *, speed: float | None = None) -> None:
        """Turn one joint by ``deg`` [deg] from where it is now."""
        self.model.joint_index(joint)
        self.move_joints({joint: self.angles()[joint] + number(deg, f"{joint} [deg]")}, speed=speed)

    def plan_grip(self, width_mm: float, *, start: Start | None = None) -> Plan:
        """``grip``'s plan from ``start`` (None: the arm now); nothing moves."""
        width = number(width_mm, "grip width [mm]") / 1000.0
        return plan_grip(start or self.start(), width)

    def grip(self, width_mm: float) -> None:
        """Open the gripper to ``width_mm`` [mm] (the grip point moves with it on
        scissor grippers). A gripper that is only open or closed (the OWI's) takes
        its closed or its open width and nothing in between (InputError)."""
        self.run(self.plan_grip(width_mm))

    def plan_home(self, *, speed: float | None = None, start: Start | None = None) -> Plan:
        """``home``'s plan from ``start`` (None: the arm now); nothing moves. From a pose
        already in the table or an object (an interrupted job, a timed arm's drifted
        estimate) the gripper first goes straight up until clear (``plan_lift_out``)."""
        timing = timing_of(speed, None, True, None)
        at = start or self.start()
        if not inside(at):
            return plan_joints(at, self.model.home, speed=timing.speed, label="home")
        lift = plan_lift_out(at)
        home = plan_joints(lift.end, self.model.home, speed=timing.speed, label="home")
        return lift.then(home, "home")

    def home(self, *, speed: float | None = None) -> None:
        """Move every joint to the model's home angles (straight up first from a pose in
        the table or an object)."""
        self.run(self.plan_home(speed=speed))

    def position(self) -> Position:
        """Where the gripper point is now [mm] and its pitch [deg]."""
        T = fk(self.start().kin, self.read())
        x, y, z = (float(v) * 1000.0 for v in T[:3, 3])
        return Position(x, y, z, math.degrees(float(pitch_of(T))))

    def angles(self) -> dict[str, float]:
        """Joint angles now [deg], by joint name."""
        q = np.degrees(self.read())
        return {name: float(a) for name, a in zip(self.model.joint_names, q, strict=True)}

    def plan_follow(
        self,
        points_mm: ArrayLike,
        pitch: float | None = None,
        *,
        streamer: Streamer | None = None,
        start: Start | None = None,
    ) -> Plan:
        """``follow``'s plan from ``start`` (None: the arm now); nothing moves."""
        if streamer is not None and not callable(getattr(streamer, "run", None)):
            raise InputError(
                "streamer must be NaiveStepping(), EarlyStreaming() or TimedStreaming() "
                f"(armkit.motion), got {streamer!r}"
            )
        pts = numbers(points_mm, "points_mm [mm]") / 1000.0
        at = start or self.start()
        return plan_follow(at, pts, pitch_radians(pitch), streamer or TimedStreaming())

    def follow(
        self, points_mm: ArrayLike, pitch: float | None = None, *, streamer: Streamer | None = None
    ) -> JointPath:
        """Draw through ``points_mm`` [mm], shape (N, 3), at ``pitch`` [deg] (None: the
        arm's own, else one for the whole path where one fits; see ``motion.plan_path``):
        the whole path is planned and checked first (PathError names the first bad
        point), then the arm moves to its start and ``streamer`` (default timed) runs it.
        An arm on timed motors (the OWI-535) follows it through waypoints its motors can
        make instead (``motion.follow``), and refuses a path its one-joint runs would
        stray from by more than ``armkit.drivers.timed.PATH_TOLERANCE``. Returns the path."""
        plan = self.plan_follow(points_mm, pitch, streamer=streamer)
        self.run(plan)
        path = plan.steps[0].path
        assert path is not None
        return path

    def plan_approach(
        self,
        x: float,
        y: float,
        z: float,
        pitch: float | None = None,
        *,
        start: Start | None = None,
    ) -> Plan:
        """``approach``'s plan from ``start`` (None: the arm now); nothing moves."""
        points = approach(numbers([x, y, z], "x, y, z [mm]") / 1000.0)
        return plan_through(start or self.start(), points, pitch_radians(pitch), "approach")

    def approach(self, x: float, y: float, z: float, pitch: float | None = None) -> None:
        """Come down onto (x, y, z) [mm] from above (001): a joint move to 30 mm
        above it, then three waypoints straight down. The whole way is checked first."""
        self.run(self.plan_approach(x, y, z, pitch))

    def plan_retreat(self, pitch: float | None = None, *, start: Start | None = None) -> Plan:
        """``retreat``'s plan from ``start`` (None: the arm now); nothing moves."""
        at = start or self.start()
        T = fk(at.kin, at.q)
        if pitch is None and not pitch_follows(at.kin):
            pitch = math.degrees(float(pitch_of(T)))
        points = retreat(np.asarray(T[:3, 3], dtype=np.float64))
        return plan_through(at, points, pitch_radians(pitch), "retreat")

    def retreat(self, pitch: float | None = None) -> None:
        """Leave the current point the way ``approach`` came: three waypoints up to
        30 mm above it, at ``pitch`` [deg] (None: keep the current pitch; on an arm whose
        pitch follows from the position, planar2, the one each point gives)."""
        self.run(self.plan_retreat(pitch))

    def run(
        self, plan: Plan, *, say: Say | None = None, wait: bool = True, timeout: float | None = None
    ) -> None:
        """Carry ``plan`` out (``say(k, step)`` before each step): the one way a command
        reaches the driver. The arm is stopped if anything goes wrong.

        Args:
            wait: block until each move is done (a one-move plan may return at once).
            timeout: give up on a move after [s] (DeviceError, the arm stopped).
        Raises:
            ArmkitError: the arm is not where the plan starts (it moved since planning);
                nothing moves then.
        """
        if not isinstance(plan, Plan):
            raise InputError(
                f"plan must be a Plan (from Arm.plan_move_to, a task's dry run, ...), got {plan!r}"
            )
        check_start(self.driver, plan)
        if self._limp:  # a move after ``relax``: the motors hold again first
            self.stiffen()
        try:
            carry_out(self.driver, self.clock, plan, say, self.settle, wait, timeout)
        finally:
            self.held = plan.end.held if plan.end.held is not None else self._held_after(plan)
        self._opening = plan.end.grip
        if plan.start.tool is not None and plan.end.tool is None:  # a grip let it go
            self.hold_tool(None)

    def _held_after(self, plan: Plan) -> Held | None:
        """What the gripper holds after (part of) ``plan``: as before unless a gripper
        step let it go."""
        let_go = any(s.grip is not None for s in plan.steps) and plan.end.held is None
        return None if let_go else self.held

    def read(self) -> F64:
        """The joint angles the driver reads now [rad], shape (dof,) (the SI read-back
        planners and views start from)."""
        return np.asarray(self.driver.read(), dtype=np.float64)

    def motor_s(self) -> float:
        """Motor-seconds the batteries have given [s] (timed motors; 0 for others)."""
        state = getattr(self.driver, "state", None)
        return float(getattr(state, "motor_s", 0.0))

    def settle(self) -> None:
        """Wait until the arm and its gripper stand still: on a simulated arm until its
        truth is at rest (at most SETTLE_MAX_S of simulated time), else GRIP_S."""
        sim = self.sim
        if sim is None:
            self.clock.sleep(GRIP_S)
            return
        waited = 0.0
        while not sim.at_rest() and waited < SETTLE_MAX_S:
            self.clock.sleep(0.01)
            waited += 0.01

    @property
    def moves(self) -> str:
        """How the driver's moves run: ``"smart"`` (serial-bus servos), ``"hobby"`` (hobby
        servos) or ``"timed"`` (motors run for a time: the OWI-535)."""
        return str(self.driver.moves)

    @property
    def uncertainty(self) -> str | None:
        """Why the joint angles may be wrong (an estimate of timed motors never homed, a
        move cut short, ...), or None when they are known."""
        reason = getattr(self.driver, "uncertainty", None)
        return None if reason is None else str(reason)

    def on_uncertain(self, tell: Callable[[str], None]) -> None:
        """Have ``tell(message)`` say it when a move starts from an uncertain estimate
        (timed motors; by default a warning)."""
        if hasattr(self.driver, "warn"):
            self.driver.warn = tell

    def analog_inputs(self) -> Any:
        """The controller's analog inputs (``read_analog(channel)``: the SSC-32's
        ``VA``..``VD``), or None if it has none."""
        device = getattr(getattr(self.driver, "bus", None), "device", None)
        return device if callable(getattr(device, "read_analog", None)) else None

    @property
    def controller(self) -> str:
        """The controller's name where the driver has one (``"ssc32"``, ``"maestro"``), else ``""``."""
        return str(getattr(getattr(self.driver, "bus", None), "name", ""))

    @property
    def can_go_limp(self) -> bool:
        """Whether the motors can go limp and the joints still be read (``relax`` then
        ``stiffen``: smart servos; hobby servos report nothing once limp)."""
        return all(callable(getattr(self.driver, n, None)) for n in ("relax", "stiffen"))

    def relax(self) -> bool:
        """Let the motors go (servos limp, torque off: support the arm first), if the
        driver can; whether it did."""
        relax = getattr(self.driver, "relax", None)
        if callable(relax):
            relax()
            self._limp = True
        return callable(relax)

    def stiffen(self) -> bool:
        """Hold the pose the arm is in now (after ``relax``), if the driver can; whether it did."""
        stiffen = getattr(self.driver, "stiffen", None)
        if callable(stiffen):
            stiffen()
        self._limp = False
        return callable(stiffen)

    @property
    def has_light(self) -> bool:
        """Whether the arm has a light (the OWI-535's)."""
        return callable(getattr(self.driver, "set_light", None))

    def set_light(self, on: bool) -> None:
        """Switch the arm's light on or off (``plan_light``; DeviceError: it has none)."""
        self.run(plan_light(self.start(), on))

    def run_motor(self, joint: str, direction: int, seconds: float) -> None:
        """Run ``joint``'s motor ``seconds`` [s] in ``direction`` (+1/-1): timed motors only
        (``plan_motor_run``; DeviceError otherwise)."""
        self.run(plan_motor_run(self.start(), joint, direction, seconds))

    def stop(self) -> None:
        """Stop every motor now."""
        self.driver.stop()

    def close(self) -> None:
        """Stop and release the driver."""
        try:
            self.driver.stop()
        finally:
            self.driver.close()

    def __enter__(self) -> Arm:
        return self

    def __exit__(
        self, kind: type[BaseException] | None, exc: BaseException | None, tb: TracebackType | None
    ) -> None:
        """Stop and close; when the block failed, its error stays the one raised (a failure
        to stop afterwards, likely from the same cause, is added to it as a note)."""
        close_after(self.close, exc)

    def _joint_target(self, angles: Mapping[str, float] | Sequence[float], now: F64) -> F64:
        if isinstance(angles, Mapping):
            q = np.degrees(now)
            for name, deg in angles.items():
                q[self.model.joint_index(name)] = number(deg, f"{name} [deg]", finite=False)
        else:
            q = numbers(angles, "joint angles [deg]", finite=False)
            if q.shape != (self.model.dof,):
                names = ", ".join(self.model.joint_names)
                raise InputError(f"give {self.model.dof} angles ({names}), got {q.size}")
        if not np.all(np.isfinite(q)):
            shown = ", ".join(f"{v:g}" for v in q)
            raise InputError(f"joint angles must be finite numbers of degrees, got {shown}")
        return np.radians(q)
