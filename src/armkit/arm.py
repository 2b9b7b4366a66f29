"""``Arm``: a model and a driver in one object, in millimetres and degrees.

The conversion to SI happens here, once; the work is done by the kinematics and
motion functions. Every move is checked (reach, joint limits, timing) before a
command goes to the driver, so a refused move moves nothing.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from pathlib import Path
from types import TracebackType
from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ._arm_inputs import Timing, number, numbers, pitch_radians, timing_of
from ._closing import close_after
from ._errors import DeviceError, InputError
from .connect import SimArm, World, open_driver, world_of
from .drivers import Driver
from .kinematics import fk, ik, pitch_follows, pitch_of
from .model import MAX_MOVE_S as MAX_MOVE_S
from .model import ArmModel, check_grip, check_joints, load_model, move_time
from .motion import (
    JointPath,
    NaiveStepping,
    Streamer,
    TimedStreaming,
    approach,
    clock_of,
    follow,
    plan_path,
    retreat,
)
from .scene import Held, Scene, load_scene, move_refusal

F64 = NDArray[np.float64]
REACHED = math.radians(0.2)  # a move with a timeout is done when every joint is this close


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
        self._kin = self.model
        self.held: Held | None = None  # a cube in the gripper: checked with the links
        self._opening: float | None = None  # the jaws' opening [m], once set

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
        timing = timing_of(speed, duration, wait, timeout)  # checked before solving
        target = numbers([x, y, z], "x, y, z [mm]") / 1000.0
        q = ik(self._kin, target, pitch_radians(pitch), self.driver.read()).q
        self._move(q, timing)

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
        self._move(self._joint_target(angles), timing)

    def turn_to(self, joint: str, deg: float, *, speed: float | None = None) -> None:
        """Turn one joint to ``deg`` [deg]; the others stay."""
        self.move_joints({joint: deg}, speed=speed)

    def turn_by(self, joint: str, deg: float, *, speed: float | None = None) -> None:
        """Turn one joint by ``deg`` [deg] from where it is now."""
        self.model.joint_index(joint)
        self.move_joints({joint: self.angles()[joint] + number(deg, f"{joint} [deg]")}, speed=speed)

    def grip(self, width_mm: float) -> None:
        """Open the gripper to ``width_mm`` [mm] (the grip point moves with it on
        scissor grippers). A gripper that is only open or closed (the OWI's) takes
        its closed or its open width and nothing in between (InputError)."""
        width = check_grip(self.model, number(width_mm, "grip width [mm]") / 1000.0)
        g = self.model.gripper
        if g.kind == "timed" and not (
            abs(width - g.width_min) < 1e-12 or abs(width - g.width_max) < 1e-12
        ):
            lo, hi = g.width_min * 1000.0, g.width_max * 1000.0
            raise InputError(
                f"{self.model.name}'s gripper is only open or closed: grip {lo:g} closes it, "
                f"grip {hi:g} opens it; got {width * 1000.0:g} mm"
            )
        kin = self.model.with_grip_width(width)
        self.driver.grip(width)
        self._kin, self._opening = kin, width
        if self.held is not None and self.held.released_by(width):
            self.held = None

    def home(self, *, speed: float | None = None) -> None:
        """Move every joint to the model's home angles."""
        self._move(self.model.home, timing_of(speed, None, True, None))

    def position(self) -> Position:
        """Where the gripper point is now [mm] and its pitch [deg]."""
        T = fk(self._kin, self.driver.read())
        x, y, z = (float(v) * 1000.0 for v in T[:3, 3])
        return Position(x, y, z, math.degrees(float(pitch_of(T))))

    def angles(self) -> dict[str, float]:
        """Joint angles now [deg], by joint name."""
        q = np.degrees(self.driver.read())
        return {name: float(a) for name, a in zip(self.model.joint_names, q, strict=True)}

    def follow(
        self, points_mm: ArrayLike, pitch: float | None = None, *, streamer: Streamer | None = None
    ) -> JointPath:
        """Draw through ``points_mm`` [mm], shape (N, 3), at ``pitch`` [deg] (None: the
        arm's own, else one for the whole path where one fits; see ``motion.plan_path``):
        the whole path is planned and checked first (PathError names the first bad
        point), then the arm moves to its start and ``streamer`` (default timed) runs it.
        An arm on timed motors (the OWI-535) follows it through waypoints its motors can
        make instead (``motion.follow``), and refuses a path its one-joint runs would
        stray from by more than ``armkit.drivers.timed.PATH_TOLERANCE``."""
        if streamer is not None and not callable(getattr(streamer, "run", None)):
            raise InputError(
                "streamer must be NaiveStepping(), EarlyStreaming() or TimedStreaming() "
                f"(armkit.motion), got {streamer!r}"
            )
        pts = numbers(points_mm, "points_mm [mm]") / 1000.0
        path = plan_path(self._kin, pts, pitch_radians(pitch), self.driver.read())
        self._check_clear(path.q)
        follow(self.driver, self._kin, path, streamer or TimedStreaming(), self.clock)
        return path

    def approach(self, x: float, y: float, z: float, pitch: float | None = None) -> None:
        """Come down onto (x, y, z) [mm] from above (001): a joint move to 30 mm
        above it, then three waypoints straight down. The whole way is checked first."""
        self._step_through(approach(numbers([x, y, z], "x, y, z [mm]") / 1000.0), pitch)

    def retreat(self, pitch: float | None = None) -> None:
        """Leave the current point the way ``approach`` came: three waypoints up to
        30 mm above it, at ``pitch`` [deg] (None: keep the current pitch; on an arm whose
        pitch follows from the position, planar2, the one each point gives)."""
        x, y, z, now = self.position()
        if pitch is None and not pitch_follows(self._kin):
            pitch = now
        self._step_through(retreat(np.array([x, y, z]) / 1000.0), pitch)

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

    def _joint_target(self, angles: Mapping[str, float] | Sequence[float]) -> F64:
        if isinstance(angles, Mapping):
            q = np.degrees(self.driver.read())
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

    def _move(self, q: F64, timing: Timing) -> None:
        """Check limits, timing (the drivers' own rule, and at most ``MAX_MOVE_S``) and
        clearance, then send; with a timeout, poll until there."""
        goal = check_joints(self.model, q)
        move_time(
            self.model,
            self.driver.read(),
            goal,
            speed=timing.speed,
            duration=timing.duration,
            longest=MAX_MOVE_S,
        )
        self._check_clear(goal[None, :])
        wait = timing.wait and timing.timeout is None
        self.driver.move(goal, duration=timing.duration, speed=timing.speed, wait=wait)
        if timing.wait and timing.timeout is not None:
            self._wait_until(goal, timing.timeout)

    def _step_through(self, points_m: F64, pitch: float | None) -> None:
        """Plan ``points_m`` [m] (1 mm tolerance between waypoints), then step through them."""
        path = plan_path(
            self._kin, points_m, pitch_radians(pitch), self.driver.read(), tolerance=1e-3
        )
        self._check_clear(path.q)
        follow(self.driver, self._kin, path, NaiveStepping(), self.clock)

    def _check_clear(self, path: F64) -> None:
        """Refuse a move from here through ``path`` (K, dof) [rad] that puts a link below the
        table, into the base column or into the scene's objects (``scene.move_refusal``)."""
        refused = move_refusal(
            self._kin, self.driver.read(), path, self.scene, self.held, self._jaws()
        )
        if refused is not None:
            raise refused

    def _jaws(self) -> float | None:
        """The jaws' opening [m]: as last set, else a simulated gripper's true one (kept
        between commands), else None (not known)."""
        sim = self.sim
        return self._opening if self._opening is not None or sim is None else sim.grip()

    def _wait_until(self, q: F64, timeout: float) -> None:
        deadline = self.clock.now() + timeout
        while np.max(np.abs(self.driver.read() - q)) > REACHED:
            if self.clock.now() >= deadline:
                self.driver.stop()
                raise DeviceError(f"the arm did not reach its target within {timeout} s; stopped")
            self.clock.sleep(0.005)
