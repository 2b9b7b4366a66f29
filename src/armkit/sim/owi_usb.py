"""A pyusb backend that IS an OWI-535: ``usb.core.find(backend=OwiUsbBackend(...))``
returns a device whose control transfers drive the simulated motors, so the
real device and driver code run unchanged on top of it.

It answers only what the arm answers: one vendor request (0x40, 6, 0x0100, 0,
3 bytes); anything else stalls, like the real board. Every transfer is kept
(and optionally appended to a log file) for byte-exact tests. Fault injection:
``present=False`` (unplugged), ``deny_access=True`` (no udev rule),
``fail_after=n`` (unplugged after n transfers).
"""

from __future__ import annotations

import errno
from dataclasses import dataclass
from pathlib import Path
from types import SimpleNamespace
from typing import Any

import numpy as np
import usb.backend
import usb.core

from ..devices.owi535 import INDEX, REQUEST, REQUEST_TYPE, VALUE, VENDOR_ID
from ..drivers.timed._commands import decode
from .owi_physics import JOINTS, OwiPhysics


@dataclass(frozen=True)
class Transfer:
    """One control transfer the host sent: setup fields and the data bytes."""

    request_type: int
    request: int
    value: int
    index: int
    data: bytes


class OwiUsbBackend(usb.backend.IBackend):  # type: ignore[misc]
    """The simulated arm behind a pyusb backend (one device on bus 1)."""

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
        self.transfers: list[Transfer] = []
        self.configuration = 0

    def enumerate_devices(self) -> list[str]:
        """One opaque device id when plugged in."""
        return ["owi535"] if self.present else []

    def get_device_descriptor(self, dev: Any) -> Any:
        """The ELAN USB device of seed 000, Figure 8."""
        return SimpleNamespace(
            bLength=18, bDescriptorType=1, bcdUSB=0x0110, bDeviceClass=0xFF,
            bDeviceSubClass=0, bDeviceProtocol=0, bMaxPacketSize0=8,
            idVendor=VENDOR_ID, idProduct=self.product_id, bcdDevice=0, iManufacturer=0,
            iProduct=0, iSerialNumber=0, bNumConfigurations=1, address=2, bus=1,
            port_number=2, port_numbers=(2,), speed=1,
        )  # fmt: skip

    def get_configuration_descriptor(self, dev: Any, config: int) -> Any:
        """Configuration 1, one vendor interface, 100 mA."""
        return SimpleNamespace(
            bLength=9, bDescriptorType=2, wTotalLength=18, bNumInterfaces=1,
            bConfigurationValue=1, iConfiguration=0, bmAttributes=0x80, bMaxPower=50,
            extra_descriptors=[],
        )  # fmt: skip

    def get_interface_descriptor(self, dev: Any, intf: int, alt: int, config: int) -> Any:
        """Interface 0, vendor class, no endpoints besides the control one."""
        return SimpleNamespace(
            bLength=9, bDescriptorType=4, bInterfaceNumber=0, bAlternateSetting=0,
            bNumEndpoints=0, bInterfaceClass=0xFF, bInterfaceSubClass=0,
            bInterfaceProtocol=0, iInterface=0, extra_descriptors=[],
        )  # fmt: skip

    def open_device(self, dev: Any) -> str:
        """A handle, or EACCES when access is denied."""
        if self.deny_access:
            raise usb.core.USBError("Access denied (insufficient permissions)", None, errno.EACCES)
        return "handle"

    def close_device(self, dev_handle: Any) -> None:
        """Nothing to release."""

    def set_configuration(self, dev_handle: Any, config_value: int) -> None:
        """Remember the configuration."""
        self.configuration = config_value

    def get_configuration(self, dev_handle: Any) -> int:
        """The configuration set last."""
        return self.configuration

    def claim_interface(self, dev_handle: Any, intf: int) -> None:
        """Nothing to claim."""

    def release_interface(self, dev_handle: Any, intf: int) -> None:
        """Nothing to release."""

    def ctrl_transfer(
        self, dev_handle: Any, bmRequestType: int, bRequest: int, wValue: int, wIndex: int,
        data: Any, timeout: int,
    ) -> int:  # fmt: skip
        """Accept the arm's one command; stall on anything else."""
        payload = bytes(data)
        self._check_alive()
        if (bmRequestType, bRequest, wValue, wIndex, len(payload)) != (
            REQUEST_TYPE, REQUEST, VALUE, INDEX, 3,
        ):  # fmt: skip
            raise usb.core.USBError("Pipe error", None, errno.EPIPE)
        self._record(Transfer(bmRequestType, bRequest, wValue, wIndex, payload))
        if self.physics is not None:
            _drive(self.physics, payload)
        return len(payload)

    def _check_alive(self) -> None:
        if not self.present or (
            self.fail_after is not None and len(self.transfers) >= self.fail_after
        ):
            self.present = False
            raise usb.core.USBError(
                "No such device (it may have been disconnected)", None, errno.ENODEV
            )

    def _record(self, transfer: Transfer) -> None:
        self.transfers.append(transfer)
        if self.log_path is not None:
            with open(self.log_path, "a") as fh:
                fh.write(transfer.data.hex() + "\n")
                fh.flush()


def _drive(physics: OwiPhysics, payload: bytes) -> None:
    """Hand a command to the motors: joint directions, gripper, light."""
    motion, light = decode(payload)
    dirs = np.array([motion.get(j, 0) for j in JOINTS], dtype=float)
    physics.command(dirs, motion.get("gripper", 0), light)
