"""A simulated OWI-535: its USB interface and the motors it runs (``owi_physics``).

``SimOwiUsb`` is the interface board as the host sees it: one vendor control
transfer (0x40, 6, 0x0100, 0, 3 data bytes, decoded with the wire codec of
``armkit.devices``); anything else stalls, like the board. It answers
``ctrl_transfer`` directly (what ``armkit.devices.owi535.OwiDevice`` calls, so
the real device class runs on it without pyusb), and ``owi_usb.OwiUsbBackend``
puts the same board behind pyusb when pyusb is installed. Every transfer is
kept (and optionally appended to a log file) for byte-exact tests. Faults:
``present=False`` (unplugged), ``deny_access=True`` (no udev rule, pyusb only),
``fail_after=n`` (unplugged after n transfers).

``OwiBody`` is the arm's physics as a world steps it.
"""

from __future__ import annotations

import errno
import math
from collections import deque
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from ..devices import owi_decode as decode
from ..devices.owi535 import INDEX, REQUEST, REQUEST_TYPE, VALUE
from ..model import ArmModel
from ._arm import Truth
from ._outbox import log
from .owi_physics import JOINTS, STEP_S, OwiPhysics

F64 = NDArray[np.float64]


@dataclass(frozen=True)
class Transfer:
    """One control transfer the host sent: setup fields and the data bytes."""

    request_type: int
    request: int
    value: int
    index: int
    data: bytes


class UsbFault(OSError):
    """What the board does to a transfer it cannot take (errno: EPIPE stall, ENODEV gone)."""


class SimOwiUsb:
    """The OWI-535's USB interface, driving ``physics`` (None: just log the transfers)."""

    def __init__(
        self,
        physics: OwiPhysics | None = None,
        *,
        product_id: int = 0,
        present: bool = True,
        deny_access: bool = False,
        fail_after: int | None = None,
        log_path: Path | None = None,
    ) -> None:
        self.physics = physics
        self.product_id = product_id
        self.present, self.deny_access, self.fail_after = present, deny_access, fail_after
        self.log_path = log_path
        self.transfers: deque[Transfer] = log()  # the last transfers accepted (bounded)
        self.count = 0  # transfers accepted, ever
        self.closed = False
        self._on_close: list[Callable[[], None]] = []

    def ctrl_transfer(
        self,
        bmRequestType: int,
        bRequest: int,
        wValue: int = 0,
        wIndex: int = 0,
        data_or_wLength: bytes | int | None = None,
        timeout: int | None = None,
    ) -> int:
        """Accept the arm's one command (returns 3); UsbFault on anything else."""
        payload = bytes(data_or_wLength) if isinstance(data_or_wLength, bytes | bytearray) else b""
        self.check_alive()
        setup = (bmRequestType, bRequest, wValue, wIndex, len(payload))
        if setup != (REQUEST_TYPE, REQUEST, VALUE, INDEX, 3):
            raise UsbFault(errno.EPIPE, "Pipe error")
        self._record(Transfer(bmRequestType, bRequest, wValue, wIndex, payload))
        if self.physics is not None:
            motion, light = decode(payload)
            dirs = np.array([motion.get(j, 0) for j in JOINTS], dtype=float)
            self.physics.command(dirs, motion.get("gripper", 0), light)
        return len(payload)

    def check_alive(self) -> None:
        """UsbFault(ENODEV) once unplugged (or after ``fail_after`` transfers)."""
        if not self.present or (self.fail_after is not None and self.count >= self.fail_after):
            self.present = False
            raise UsbFault(errno.ENODEV, "No such device (it may have been disconnected)")

    def on_close(self, action: Callable[[], None]) -> None:
        """Run ``action`` once when the host lets go of the board."""
        self._on_close.append(action)

    def close(self) -> None:
        """The host let go of the board (the close actions run once)."""
        self.closed = True
        actions, self._on_close = self._on_close, []
        for action in actions:
            action()

    def _record(self, transfer: Transfer) -> None:
        self.transfers.append(transfer)
        self.count += 1
        if self.log_path is not None:
            with open(self.log_path, "a") as fh:
                fh.write(transfer.data.hex() + "\n")
                fh.flush()


class OwiBody:
    """The OWI-535's motors as a world steps them (``_arm.Body``). The motors integrate
    in steps of ``owi_physics.STEP_S`` (20 ms: they are slow, and the unit's gravity and
    battery terms are costly) and exactly up to every command; the world's 1 kHz
    recording shows the truth as of the last of those. The gripper is open or closed
    or between: its opening [m] is the model's range times the travel."""

    def __init__(self, model: ArmModel, physics: OwiPhysics) -> None:
        self.model, self.physics = model, physics
        self._stop: float | None = None

    def step(self, t: float, dt: float) -> None:
        """Integrate the motors up to ``t`` [s] once a whole integration step is due."""
        if t >= self.physics.t + STEP_S - 1e-12:
            self.physics.advance(t)
        if self._stop is not None and self.grip() < self._stop:
            self.physics.gripper = self._fraction(self._stop)

    def q(self) -> F64:
        """True joint angles [rad], shape (4,)."""
        return self.physics.q

    def grip(self) -> float:
        """True gripper opening [m]."""
        g = self.model.gripper
        return g.width_min + self.physics.gripper * (g.width_max - g.width_min)

    def grip_stop(self, width: float | None) -> None:
        """Jaws stop at ``width`` [m] while closing (None: free)."""
        self._stop = width

    def at_rest(self) -> bool:
        """True when no motor runs."""
        return not np.any(self.physics.dirs) and self.physics.gripper_dir == 0

    def truth(self) -> Truth:
        """Angles, opening and battery use, to keep between processes."""
        return Truth(tuple(float(a) for a in self.physics.q), self.grip(), self.physics.motor_s)

    def _fraction(self, width: float) -> float:
        g = self.model.gripper
        span = g.width_max - g.width_min
        return 0.0 if span <= 0 else min(1.0, max(0.0, (width - g.width_min) / span))

    def restore(self, truth: Truth) -> None:
        """Put the physics where ``truth`` says (a new process continuing the last)."""
        self.physics.q = np.array(truth.q, dtype=np.float64)
        self.physics.gripper = self._fraction(truth.grip)
        self.physics.motor_s = truth.motor_s if math.isfinite(truth.motor_s) else 0.0
