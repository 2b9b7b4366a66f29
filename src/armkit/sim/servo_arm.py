"""A simulated servo arm behind the Driver interface (``--driver sim`` for servo arms).

Time is virtual: nothing happens until the caller waits, either through a
blocking ``move``/``grip`` or through the driver's ``clock.sleep``, which
advances the simulation in 1 ms steps. So a 20 s drawing simulates in well
under a second, and every step's true joint angles are recorded.

``port`` is a state file (JSON) or None. With a file, the arm starts where the
file says and writes its final joint angles and grip back on ``close`` (atomic
replace), so that one CLI process can ``move`` and the next one ask ``where``.
``default_state_file`` is where the CLI keeps it: ``$ARMKIT_CONFIG_DIR``, else
``$XDG_CONFIG_HOME/armkit``, else ``~/.config/armkit``.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._errors import DeviceError, JointLimitError
from .._files import config_dir
from ..model import ArmModel
from ..motion._profiles import trapezoid_in_line
from .servo_dynamics import ServoBank, ServoParams
from .servo_record import Recorder, Recording, rounded_steps
from .servo_state import load_state, save_state

F64 = NDArray[np.float64]
GRIPPER_SPEED = 0.05  # [m/s]
MAX_WAIT = 60.0  # longest blocking wait [s of simulated time]


class SimClock:
    """The simulation's virtual time; ``sleep`` runs the simulation forward."""

    def __init__(self, arm: ServoArmSim) -> None:
        self._arm = arm

    def now(self) -> float:
        """Simulated time [s] since the arm was opened."""
        return self._arm.time

    def sleep(self, seconds: float) -> None:
        """Advance the simulation by ``seconds`` (rounded up to whole steps)."""
        self._arm.advance(seconds)


class ServoArmSim:
    """Simulated servos for every joint of ``model`` plus a gripper (see module doc).

    Attributes:
        model: the arm.  params: servo behaviour.  clock: virtual time.
        commands: how many commands (move, grip) were accepted; refused ones don't count.
    """

    def __init__(
        self,
        model: ArmModel,
        params: ServoParams,
        q0: F64,
        grip0: float,
        state_file: str | None = None,
    ) -> None:
        self.model = model
        self.params = params
        vmax = np.array([j.max_velocity for j in model.joints])
        self.bank = ServoBank(q0, vmax, params)
        self.grip_width = grip0
        self._grip_goal = grip0
        self.clock = SimClock(self)
        self.commands = 0
        self.time = 0.0
        self._steps = 0
        self._closed = False
        self._state_file = state_file
        self._recorder = Recorder(model.joint_names)
        self._recorder.add(0.0, self.bank.joint)

    @property
    def joint_names(self) -> tuple[str, ...]:
        """Joint names in model order."""
        return self.model.joint_names

    def move(
        self,
        q: NDArray[np.float64],
        *,
        duration: float | None = None,
        speed: float | None = None,
        wait: bool = True,
    ) -> None:
        """Move to ``q`` [rad]: linear over ``duration`` [s] (stretched if a joint
        would exceed ``speed`` x its max velocity), else a trapezoid shared by all
        joints (a straight joint-space line, like a Dynamixel time-based profile)."""
        goal = self._checked(q)
        frac = 1.0 if speed is None else speed
        if duration is None:
            prof = trapezoid_in_line(self.model, self.bank.setpoint, goal, frac)
            self.bank.command_profile(goal, prof.v, prof.a)
        else:
            self.bank.command_linear(goal, self._stretched(goal, duration, frac))
        self.commands += 1
        if wait:
            self._wait_for(self.bank.settled)

    def read(self) -> NDArray[np.float64]:
        """True joint angles [rad], shape (dof,)."""
        return self.bank.joint.copy()

    def grip(self, width: float) -> None:
        """Open the gripper to ``width`` [m] and wait until it is there."""
        self._alive()
        g = self.model.gripper
        if not (math.isfinite(width) and g.width_min - 1e-12 <= width <= g.width_max + 1e-12):
            lo, hi = g.width_min * 1000, g.width_max * 1000
            raise ValueError(f"grip width {width * 1000:.1f} mm is outside {lo:.1f}..{hi:.1f} mm")
        self._grip_goal = width
        self.commands += 1
        self._wait_for(lambda: self.grip_width == self._grip_goal)

    def stop(self) -> None:
        """Freeze every joint's setpoint where it is."""
        self.bank.halt()
        self._grip_goal = self.grip_width

    def close(self) -> None:
        """Stop; if a command was accepted and there is a state file, let the servos
        finish settling (as they do after the program exits) and write it."""
        if self._closed:
            return
        self.stop()
        self._closed = True
        if self._state_file is not None and self.commands:
            self._wait_for(lambda: bool(np.allclose(self.bank.motor, self.bank.goal, atol=1e-9)))
            save_state(self._state_file, self.model.name, self.bank.joint, self.grip_width)

    def advance(self, seconds: float) -> None:
        """Run the simulation for ``seconds`` of simulated time."""
        for _ in range(rounded_steps(seconds, self.params.dt)):
            self._step()

    def recording(self) -> Recording:
        """Every step's true joint angles since the arm was opened."""
        return self._recorder.recording()

    def _step(self) -> None:
        self.bank.step()
        dg = GRIPPER_SPEED * self.params.dt
        self.grip_width += float(np.clip(self._grip_goal - self.grip_width, -dg, dg))
        self._steps += 1
        self.time = self._steps * self.params.dt
        self._recorder.add(self.time, self.bank.joint)

    def _wait_for(self, done: Callable[[], bool]) -> None:
        for _ in range(rounded_steps(MAX_WAIT, self.params.dt)):
            if done():
                return
            self._step()
        raise DeviceError(f"simulated arm did not finish its move within {MAX_WAIT:.0f} s")

    def _checked(self, q: ArrayLike) -> F64:
        self._alive()
        goal = np.asarray(q, dtype=np.float64)
        if goal.shape != (self.model.dof,) or not np.all(np.isfinite(goal)):
            raise ValueError(f"q must be {self.model.dof} finite angles, got {q!r}")
        bad = ~((goal >= self.model.lower - 1e-9) & (goal <= self.model.upper + 1e-9))
        if np.any(bad):
            i = int(np.argmax(bad))
            j = self.model.joints[i]
            raise JointLimitError(
                f"{j.name} {math.degrees(goal[i]):.2f} deg is outside its limits "
                f"{math.degrees(j.lower):.2f}..{math.degrees(j.upper):.2f} deg"
            )
        return goal

    def _stretched(self, goal: F64, duration: float, speed: float) -> float:
        if not (math.isfinite(duration) and duration >= 0) or not 0 < speed <= 1:
            raise ValueError(f"need duration >= 0 s and speed in (0, 1], got {duration}, {speed}")
        vmax = speed * self.bank.motor_vmax / self.params.motor_speed_margin
        return max(duration, float(np.max(np.abs(goal - self.bank.setpoint) / vmax)))

    def _alive(self) -> None:
        if self._closed:
            raise DeviceError("the simulated arm is closed")


def sim_params_for(model: ArmModel) -> ServoParams:
    """Servo behaviour for ``model``: smart servos (Dynamixel) lag less than hobby servos."""
    return ServoParams(lag=0.010) if "dynamixel" in model.drivers else ServoParams(lag=0.025)


def open_servo_sim(
    model: ArmModel, port: str | None = None, params: ServoParams | None = None
) -> ServoArmSim:
    """A simulated servo arm for ``model``, at home with the gripper open, or, with
    ``port`` a state file path, where that file left it (see the module doc).
    ``params`` overrides the servo behaviour (lag, backlash, ...)."""
    q0, grip0 = model.home, model.gripper.width_max
    if port is not None:
        state = load_state(port, model)
        if state is not None:
            q0, grip0 = state
    return ServoArmSim(model, params or sim_params_for(model), q0, grip0, port)


def default_state_file(model: ArmModel) -> str:
    """Where the CLI keeps the simulated ``model``'s state between invocations."""
    return str(config_dir() / f"sim_{model.name}.json")
