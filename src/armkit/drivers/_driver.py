"""The one small interface every driver implements.

A driver turns the model's *kinematic* joint angles [rad] into device commands
and back. Everything a person types (mm, degrees) is converted above this
layer, in ``Arm`` and the CLI.
"""

from __future__ import annotations

from typing import Protocol, runtime_checkable

import numpy as np
from numpy.typing import NDArray


@runtime_checkable
class Driver(Protocol):
    """Joint angles <-> a device.

    Every method validates before sending a byte: a refused command raises
    (``JointLimitError``, ``ValueError``, ``DeviceError``) and changes nothing.
    """

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
