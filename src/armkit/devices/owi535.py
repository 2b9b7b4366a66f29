"""The OWI-535 USB interface: find it with pyusb and send its 3-byte commands.

One vendor control transfer per command (seed 000, section 2): bmRequestType
0x40, bRequest 6, wValue 0x0100, wIndex 0, 3 data bytes (``encode``/``decode``:
the wire codec). pyusb is imported only when a device is opened, so
``import armkit`` never needs it. ``OwiDevice`` needs of its USB device only
``ctrl_transfer`` (pyusb's signature): ``attach`` puts it on any object that has
it (a simulated board where pyusb is not installed).
"""

from __future__ import annotations

import errno
import sys
import threading
from collections.abc import Callable
from typing import Any, Protocol

from .._errors import DeviceError, InputError
from ._owi_commands import decode as decode
from ._owi_commands import encode as encode

VENDOR_ID = 0x1267
PRODUCT_IDS = (0x0000, 0x0001)
REQUEST_TYPE = 0x40
REQUEST = 6
VALUE = 0x0100
INDEX = 0
TIMEOUT_MS = 1000
UDEV_RULE = 'SUBSYSTEM=="usb", ATTR{idVendor}=="1267", MODE="0660", GROUP="plugdev", TAG+="uaccess"'


class UsbControl(Protocol):
    """What armkit uses of a USB device: one control transfer (pyusb's signature)."""

    def ctrl_transfer(
        self,
        bmRequestType: int,
        bRequest: int,
        wValue: int = 0,
        wIndex: int = 0,
        data_or_wLength: Any = None,
        timeout: int | None = None,
    ) -> Any:
        """Send a control transfer; raises on a stall or a vanished device."""
        ...


class OwiDevice:
    """An opened OWI-535 USB interface. Thread-safe: a watchdog may send a stop
    while the main thread is between commands.

    Args:
        dev: the USB device (a pyusb ``Device``, or any ``UsbControl``).
        release: called once by ``close`` to let go of ``dev``.
    """

    def __init__(self, dev: UsbControl, release: Callable[[], None] | None = None) -> None:
        self._dev = dev
        self._release = release
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
        if self._release is not None:
            self._release()


def attach(dev: UsbControl, release: Callable[[], None] | None = None) -> OwiDevice:
    """An ``OwiDevice`` on an already-open USB device (no pyusb needed)."""
    return OwiDevice(dev, release)


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
    import usb.util

    return OwiDevice(dev, lambda: usb.util.dispose_resources(dev))


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
