"""A pyusb backend that IS an OWI-535: ``usb.core.find(backend=OwiUsbBackend(...))``
returns a device whose control transfers go to a simulated interface board
(``owi535.SimOwiUsb``), so pyusb, the real device class and the real driver run
unchanged on top of it. Imported only where pyusb is installed.
"""

from __future__ import annotations

import errno
from types import SimpleNamespace
from typing import Any

import usb.backend
import usb.core

from ..devices.owi535 import VENDOR_ID
from .owi535 import SimOwiUsb, Transfer, UsbFault

__all__ = ["OwiUsbBackend", "Transfer"]


class OwiUsbBackend(usb.backend.IBackend):  # type: ignore[misc]
    """A simulated board (``board``, default a plain ``SimOwiUsb()``: no physics, just
    the transfers logged) behind a pyusb backend: one device on bus 1."""

    def __init__(self, board: SimOwiUsb | None = None) -> None:
        self.board = board or SimOwiUsb()
        self.configuration = 0

    @property
    def transfers(self) -> list[Transfer]:
        """The transfers the board accepted (the last ``LOG_ROWS``), oldest first."""
        return list(self.board.transfers)

    @property
    def present(self) -> bool:
        """False once unplugged."""
        return self.board.present

    @present.setter
    def present(self, value: bool) -> None:
        self.board.present = value

    def enumerate_devices(self) -> list[str]:
        """One opaque device id when plugged in."""
        return ["owi535"] if self.board.present else []

    def get_device_descriptor(self, dev: Any) -> Any:
        """The ELAN USB device of seed 000, Figure 8."""
        return SimpleNamespace(
            bLength=18, bDescriptorType=1, bcdUSB=0x0110, bDeviceClass=0xFF,
            bDeviceSubClass=0, bDeviceProtocol=0, bMaxPacketSize0=8,
            idVendor=VENDOR_ID, idProduct=self.board.product_id, bcdDevice=0, iManufacturer=0,
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
        if self.board.deny_access:
            raise usb.core.USBError("Access denied (insufficient permissions)", None, errno.EACCES)
        return "handle"

    def close_device(self, dev_handle: Any) -> None:
        """The host let go of the board."""
        self.board.close()

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
        """Hand the transfer to the board; its faults become pyusb's USBError."""
        try:
            return self.board.ctrl_transfer(bmRequestType, bRequest, wValue, wIndex, bytes(data))
        except UsbFault as exc:
            raise usb.core.USBError(exc.strerror, None, exc.errno) from None
