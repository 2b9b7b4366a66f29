"""The one error of a serial port that has gone away (a USB adapter pulled out)."""

from __future__ import annotations

from .._errors import DeviceError


class PortGoneError(DeviceError):
    """The port itself failed (OS or pyserial error): no retry or other servo can help."""


def gone(device: str, port: str, what: str, exc: BaseException) -> PortGoneError:
    """The error for ``what`` failing with ``exc`` on ``port`` of ``device``."""
    return PortGoneError(
        f"{device} on {port}: {what} failed: {exc}; the port has gone "
        "(unplugged, powered off?): plug it back in and start again"
    )
