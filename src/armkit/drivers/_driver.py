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
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Protocol, runtime_checkable

import numpy as np
from numpy.typing import NDArray

if TYPE_CHECKING:
    from ..model import ArmModel

F64 = NDArray[np.float64]


@runtime_checkable
class Driver(Protocol):
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


def pieces(q0: F64, q1: F64, total: float, longest: float) -> list[tuple[F64, float]]:
    """A move of ``total`` [s] from ``q0`` to ``q1`` [rad] along the line, cut into equal
    pieces of at most ``longest`` [s]: [(end of the piece, its time [s]), ...]."""
    count = max(1, math.ceil(total / longest - 1e-9))
    return [(q0 + (q1 - q0) * (k / count), total / count) for k in range(1, count + 1)]
