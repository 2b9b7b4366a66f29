"""The OWI-535 USB interface: find it with pyusb and send its 3-byte commands.

One vendor control transfer per command (seed 000, section 2): bmRequestType
0x40, bRequest 6, wValue 0x0100, wIndex 0, 3 data bytes. pyusb is imported
only when a device is opened, so ``import armkit`` never needs it.
"""

from __future__ import annotations

import errno
import sys
import threading
from typing import Any

from .._errors import DeviceError, InputError

VENDOR_ID = 0x1267
PRODUCT_IDS = (0x0000, 0x0001)
REQUEST_TYPE = 0x40
REQUEST = 6
VALUE = 0x0100
INDEX = 0
TIMEOUT_MS = 1000
UDEV_RULE = 'SUBSYSTEM=="usb", ATTR{idVendor}=="1267", MODE="0660", GROUP="plugdev", TAG+="uaccess"'


class OwiDevice:
    """An opened OWI-535 USB interface. Thread-safe: a watchdog may send a stop
    while the main thread is between commands."""

    def __init__(self, dev: Any) -> None:
        self._dev = dev
        self._lock = threading.Lock()
        self._closed = False

    def send(self, data: bytes) -> None:
        """Send one 3-byte command.

        Raises:
            DeviceError: the transfer failed (unplugged, batteries, permissions).
        """
        if len(data) != 3:
            raise InputError(f"an OWI-535 command has 3 bytes, got {len(data)}")
        with self._lock:
            if self._closed:
                raise DeviceError("the OWI-535 device is closed; open the driver again")
            try:
                self._dev.ctrl_transfer(REQUEST_TYPE, REQUEST, VALUE, INDEX, data, TIMEOUT_MS)
            except Exception as exc:  # pyusb raises USBError; keep the type local
                raise DeviceError(
                    f"sending {data.hex(' ')} to the OWI-535 failed ({exc}); check the USB "
                    "cable and the arm's power switch and batteries"
                ) from exc

    def close(self) -> None:
        """Release the device (no byte is sent). Safe to call twice."""
        with self._lock:
            if self._closed:
                return
            self._closed = True
        import usb.util

        usb.util.dispose_resources(self._dev)


def open_device(backend: Any = None) -> OwiDevice:
    """Find the first OWI-535 (vendor 0x1267, product 0 or 1) and configure it.

    Args:
        backend: a pyusb backend; None = libusb from ``libusb-package``, else
            pyusb's own search.

    Raises:
        DeviceError: pyusb or a libusb backend is missing, no arm is plugged
            in, or the operating system refused access; the message says what to do.
    """
    usb_core = _import_usb()
    if backend is None:
        backend = _default_backend()
    try:
        dev = usb_core.find(backend=backend, idVendor=VENDOR_ID, custom_match=_is_owi)
    except usb_core.NoBackendError:
        raise DeviceError(_no_backend_message()) from None
    if dev is None:
        raise DeviceError(
            "no OWI-535 USB interface found (vendor 0x1267, product 0 or 1); plug it in, "
            "switch the arm on, or use --driver sim"
        )
    _configure(dev, usb_core)
    return OwiDevice(dev)


def _is_owi(dev: Any) -> bool:
    return dev.idProduct in PRODUCT_IDS


def _configure(dev: Any, usb_core: Any) -> None:
    try:
        dev.set_configuration()
    except usb_core.USBError as exc:
        if exc.errno in (errno.EACCES, errno.EPERM):
            raise DeviceError(_permission_message()) from None
        if exc.errno != errno.EBUSY:
            raise DeviceError(
                f"cannot configure the OWI-535 ({exc}); unplug and replug it"
            ) from None


def _import_usb() -> Any:
    try:
        import usb.core
    except ModuleNotFoundError:
        raise DeviceError(
            "the owi535 driver needs pyusb; install it with: pip install 'armkit[usb]'"
        ) from None
    return usb.core


def _default_backend() -> Any:
    try:
        import libusb_package
    except ModuleNotFoundError:
        return None
    return libusb_package.get_libusb1_backend()


def _permission_message() -> str:
    return (
        "permission denied opening the OWI-535; allow non-root access with a udev rule: "
        f"echo '{UDEV_RULE}' | sudo tee /etc/udev/rules.d/50-owi535.rules, "
        "then 'sudo udevadm control --reload-rules' and replug the arm"
    )


def _no_backend_message() -> str:
    if sys.platform.startswith("win"):
        return (
            "no libusb backend for pyusb: install the libusb-win32 driver for the arm "
            "with Zadig (https://zadig.akeo.ie), and pip install 'armkit[usb]'"
        )
    return (
        "no libusb backend for pyusb: pip install 'armkit[usb]' (ships libusb-package), "
        "or install libusb-1.0 with your package manager"
    )
