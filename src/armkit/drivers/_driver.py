"""The one small interface every driver implements, and the contract that goes with it.

A driver turns the model's *kinematic* joint angles [rad] into device commands
and back. Everything a person types (mm, degrees) is converted above this
layer, in ``Arm`` and the CLI.

The contract (what a driver may assume, what it must check)
-----------------------------------------------------------

A driver may assume nothing about its caller: ``Arm`` checks a move before it
calls the driver, but scripts, streamers and tests call drivers directly, and
the driver is the last line before the hardware. So every driver checks every
command completely before the first byte goes out, with the shared rules of
``armkit.model._limits`` (one implementation, so ``Arm`` and every driver
accept and refuse exactly the same moves):

- ``move(q, duration, speed, wait)``: ``check_joints`` (shape, finite, every
  joint inside the model's limits: JointLimitError naming the joint), then
  ``move_time`` for the timing: without ``duration`` the move takes the shortest
  rest-to-rest trapezoid along the straight joint-space line within every joint's
  ``speed`` x max velocity and its max acceleration; with ``duration`` it takes
  exactly that long, refused (ValueError) if a joint would need more than
  ``speed`` x its max velocity. Never stretched silently. A driver whose device
  cannot do a legal move in one command (an SSC-32 move lasts at most 65.5 s, a
  Dynamixel profile 32.7 s) splits it into pieces along the line and waits
  between them; ``wait=False`` with such a move is refused (ValueError). A device
  with fixed motor speed (the OWI-535) cannot slow down: it checks the same
  rule, then moves at its own speed and says so in its docs.
- ``grip(width)``: ``check_grip`` (ValueError in mm outside the model's range).
- A refused command raises (``JointLimitError``, ``ValueError``, ``DeviceError``)
  and changes nothing: no byte, no state written.
- A driver may assume its device is the one its model describes (IDs, channels
  from the model's driver section) and must say so (DeviceError naming what it
  found) when it is not.
- ``stop`` is safe at any time, repeatedly; ``close`` stops, releases the
  device and is safe to call twice; after it every command raises DeviceError.
- Time: a driver waits only through its ``clock`` attribute (an
  ``armkit._clock.Clock``: the wall clock on hardware, the world's on a
  simulated device), never ``time.sleep``, so a simulation runs in its own time.
- ``forecast(q0, q1, ...)`` and ``forecast_grip(before, width)`` say what ``move``
  and ``grip`` will do (how long they take, their waits included, and where the
  driver will read the joints after), from any pose, with no byte sent: ``Arm``
  plans every motion with them, so a plan's time is what running it takes. They
  refuse what ``move`` refuses.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Protocol, runtime_checkable

import numpy as np
from numpy.typing import NDArray

if TYPE_CHECKING:
    from ..model import ArmModel

F64 = NDArray[np.float64]


@dataclass(frozen=True)
class Forecast:
    """What one ``move`` will do, worked out before it is sent.

    Attributes:
        seconds: how long the command takes, its waits included [s].
        q: the joint angles the driver will read after it [rad], shape (dof,).
        motor_s: motor-seconds the batteries have given after it [s] (timed motors
            slow down with it; other drivers pass it on unchanged).
    """

    seconds: float
    q: F64
    motor_s: float = 0.0


@runtime_checkable
class Forecaster(Protocol):
    """What a driver will do, without a device: every ``Driver`` is one, and a driver
    kind gives one for a model alone (``armkit.connect.forecaster``) for ``armkit check``.

    Attributes:
        moves: how its moves run, as its kind's trait (``armkit.connect.Trait``):
            ``"smart"`` (serial-bus servos, one timed profile per move), ``"hobby"``
            (hobby servos, one group move of constant pulse speed) or ``"timed"`` (motors
            run one joint at a time for a time).
    """

    @property
    def moves(self) -> str:
        """``"smart"``, ``"hobby"`` or ``"timed"`` (see above)."""
        ...

    def forecast(
        self,
        q0: F64,
        q1: F64,
        *,
        duration: float | None = None,
        speed: float | None = None,
        motor_s: float = 0.0,
    ) -> Forecast:
        """What ``move(q1, duration=, speed=, wait=True)`` does from ``q0`` [rad], shape
        (dof,), with ``motor_s`` [s] used; raises what ``move`` would raise."""
        ...

    def forecast_grip(self, before: float | None, width: float) -> float:
        """How long ``grip(width)`` [m] takes [s] from an opening of ``before`` [m] (None:
        not known); raises what ``grip`` would raise."""
        ...


@runtime_checkable
class Driver(Forecaster, Protocol):
    """Joint angles <-> a device (see the module doc for the contract)."""

    @property
    def joint_names(self) -> tuple[str, ...]:
        """Names of the joints this driver moves, in model order."""
        ...

    def move(
        self,
        q: NDArray[np.float64],
        *,
        duration: float | None = None,
        speed: float | None = None,
        wait: bool = True,
    ) -> None:
        """Move every joint to ``q`` [rad], shape (dof,), all arriving together.

        Args:
            duration: time for the move [s]; None = as fast as the limits allow.
            speed: fraction of each joint's maximum velocity, (0, 1]; None = 1.
            wait: block until the move is done.
        """
        ...

    def read(self) -> NDArray[np.float64]:
        """Current (or best-estimate) joint angles [rad], shape (dof,)."""
        ...

    def grip(self, width: float) -> None:
        """Set the gripper opening ``width`` [m]."""
        ...

    def stop(self) -> None:
        """Stop every motor now. Safe to call at any time, repeatedly."""
        ...

    def close(self) -> None:
        """Stop, release the device. Safe to call twice."""
        ...


@runtime_checkable
class PathFollower(Protocol):
    """A driver that cannot follow a stream of small moves and follows a whole path its
    own way (timed motors: waypoints one joint at a time, ``TimedDriver``)."""

    def follow_path(self, model: ArmModel, q: F64, points: F64) -> object:
        """Follow joint path ``q`` [rad], (N, dof), whose tool points are ``points`` [m],
        (N, 3), solved with ``model``; everything checked before a motor starts."""
        ...


@runtime_checkable
class PathForecaster(Protocol):
    """Forecasts of a ``PathFollower``'s own way along a path (timed motors)."""

    def forecast_path(
        self, model: ArmModel, q0: F64, q: F64, points: F64, motor_s: float
    ) -> Forecast:
        """What ``follow_path(model, q, points)`` does from ``q0`` [rad] with ``motor_s`` [s]
        used, the move onto its start included; raises what it would raise."""
        ...


@runtime_checkable
class RunForecaster(Protocol):
    """Forecasts of a motor's own timed run (the OWI-535's)."""

    def forecast_run(
        self, q0: F64, joint: str, direction: int, seconds: float, motor_s: float
    ) -> Forecast:
        """What ``turn_for(joint, direction, seconds)`` does from ``q0`` [rad]."""
        ...


@runtime_checkable
class TimedMotors(RunForecaster, Protocol):
    """A driver of motors run for a time (the OWI-535): a motor's own run and the
    board's light."""

    def turn_for(self, joint: str, direction: int, seconds: float) -> None:
        """Run ``joint``'s motor ``seconds`` [s] in ``direction`` (+1/-1)."""
        ...

    def set_light(self, on: bool) -> None:
        """Switch the light on or off."""
        ...


def pieces(q0: F64, q1: F64, total: float, longest: float) -> list[tuple[F64, float]]:
    """A move of ``total`` [s] from ``q0`` to ``q1`` [rad] along the line, cut into equal
    pieces of at most ``longest`` [s]: [(end of the piece, its time [s]), ...]."""
    count = max(1, math.ceil(total / longest - 1e-9))
    return [(q0 + (q1 - q0) * (k / count), total / count) for k in range(1, count + 1)]
