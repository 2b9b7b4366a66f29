"""Finding the arm over pyusb, and every way that can fail."""

from __future__ import annotations

import sys

import pytest
import usb.core

import armkit.devices.owi535 as owi_usb
from armkit._errors import DeviceError
from armkit.devices.owi535 import open_device
from armkit.sim.owi535 import SimOwiUsb
from armkit.sim.owi_usb import OwiUsbBackend


@pytest.mark.parametrize("product", [0, 1])
def test_found_by_vendor_and_product_0_or_1(product: int) -> None:
    backend = OwiUsbBackend(SimOwiUsb(product_id=product))
    dev = open_device(backend)
    dev.send(b"\x80\x00\x00")
    assert backend.configuration == 1
    assert [t.data for t in backend.transfers] == [b"\x80\x00\x00"]


def test_other_product_is_not_the_arm() -> None:
    with pytest.raises(DeviceError, match="no OWI-535 USB interface found"):
        open_device(OwiUsbBackend(SimOwiUsb(product_id=5)))


def test_not_plugged_in() -> None:
    with pytest.raises(DeviceError, match="plug it in"):
        open_device(OwiUsbBackend(SimOwiUsb(present=False)))


def test_permission_denied_gives_the_udev_rule() -> None:
    with pytest.raises(DeviceError) as info:
        open_device(OwiUsbBackend(SimOwiUsb(deny_access=True)))
    message = str(info.value)
    assert 'ATTR{idVendor}=="1267"' in message and "/etc/udev/rules.d" in message


@pytest.mark.parametrize(("platform", "hint"), [("linux", "libusb-package"), ("win32", "Zadig")])
def test_no_backend_says_what_to_install(
    monkeypatch: pytest.MonkeyPatch, platform: str, hint: str
) -> None:
    def no_backend(**_kwargs: object) -> None:
        raise usb.core.NoBackendError("No backend available")

    monkeypatch.setattr(usb.core, "find", no_backend)
    monkeypatch.setattr(sys, "platform", platform)
    with pytest.raises(DeviceError, match=hint):
        open_device()


def test_default_backend_comes_from_libusb_package(monkeypatch: pytest.MonkeyPatch) -> None:
    seen: dict[str, object] = {}

    def fake_find(**kwargs: object) -> None:
        seen.update(kwargs)

    monkeypatch.setattr(usb.core, "find", fake_find)
    with pytest.raises(DeviceError):
        open_device()
    import libusb_package

    assert type(seen["backend"]) is type(libusb_package.get_libusb1_backend())


def test_unplugged_mid_session_is_a_device_error() -> None:
    dev = open_device(OwiUsbBackend(SimOwiUsb(fail_after=1)))
    dev.send(b"\x00\x00\x00")
    with pytest.raises(DeviceError, match="check the USB cable"):
        dev.send(b"\x40\x00\x00")


def test_closed_device_refuses_and_close_is_idempotent() -> None:
    dev = open_device(OwiUsbBackend())
    dev.close()
    dev.close()
    with pytest.raises(DeviceError, match="closed"):
        dev.send(b"\x00\x00\x00")


def test_import_armkit_does_not_import_usb() -> None:
    import subprocess

    code = "import armkit, armkit.drivers.timed, armkit.cli, sys; print('usb' in sys.modules)"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "False"
    assert owi_usb.VENDOR_ID == 0x1267
