"""The XM430-W350 control table as data: addresses, sizes, signedness."""

from __future__ import annotations

import itertools

import pytest

from armkit import InputError
from armkit.devices import _xm430 as xm

HARDWARE_MD = {  # name: (address, size), from shared/reference/hardware.md
    "Model Number": (0, 2),
    "ID": (7, 1),
    "Baud Rate": (8, 1),
    "Drive Mode": (10, 1),
    "Operating Mode": (11, 1),
    "Homing Offset": (20, 4),
    "Torque Enable": (64, 1),
    "Hardware Error Status": (70, 1),
    "Profile Acceleration": (108, 4),
    "Profile Velocity": (112, 4),
    "Goal Position": (116, 4),
    "Moving": (122, 1),
    "Present Current": (126, 2),
    "Present Velocity": (128, 4),
    "Present Position": (132, 4),
    "Present Input Voltage": (144, 2),
    "Present Temperature": (146, 1),
}


@pytest.mark.parametrize(("name", "where"), HARDWARE_MD.items())
def test_addresses_and_sizes(name: str, where: tuple[int, int]) -> None:
    reg = xm.register(name)
    assert (reg.address, reg.size) == where


def test_registers_do_not_overlap_and_fit_the_table() -> None:
    regs = sorted(xm.XM430_W350.values(), key=lambda r: r.address)
    for a, b in itertools.pairwise(regs):
        assert a.address + a.size <= b.address, (a.name, b.name)
    assert regs[-1].address + regs[-1].size == xm.CONTROL_TABLE_SIZE


def test_present_state_is_signed_and_sdk_values_are_fixed() -> None:
    for name in ("Present Current", "Present Velocity", "Present Position", "Homing Offset"):
        assert xm.register(name).signed
    assert xm.register("Present Velocity").from_unsigned(0xFFFFFFF6) == -10
    assert xm.register("Present Current").from_unsigned(0xFFFF) == -1
    assert xm.register("Moving").from_unsigned(1) == 1


def test_encode_refuses_values_that_do_not_fit() -> None:
    assert xm.register("Goal Position").encode(-1) == b"\xff\xff\xff\xff"
    with pytest.raises(ValueError, match="Torque Enable"):
        xm.register("Torque Enable").encode(256)


def test_eeprom_and_unknown_names() -> None:
    assert xm.register("Operating Mode").eeprom and not xm.register("Goal Position").eeprom
    with pytest.raises(InputError, match="Goal Position"):
        xm.register("Goal Positon")
    assert xm.describe_hardware_error(0x24) == "overheating, overload"
