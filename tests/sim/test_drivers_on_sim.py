"""``--driver sim`` runs every arm's own hardware driver: the class the real device gets."""

from __future__ import annotations

import typing
from collections.abc import Callable

import pytest

from armkit.connect import native_kind, open_driver, world_of
from armkit.drivers import dynamixel, feetech, servo, timed
from armkit.model import load_model, shipped_models

# each kind's opener of real hardware, as the registry's entry calls it
REAL_OPENERS: dict[str, Callable[..., object]] = {
    "owi535": timed.open_owi535,
    "ssc32": servo.open_ssc32,
    "maestro": servo.open_maestro,
    "dynamixel": dynamixel.open_dynamixel,
    "feetech": feetech.open_feetech,
}


def hardware_class(driver: str) -> type:
    """The class the opener of real hardware returns (its return annotation)."""
    cls = typing.get_type_hints(REAL_OPENERS[driver])["return"]
    assert isinstance(cls, type)
    return cls


@pytest.mark.parametrize("arm", shipped_models())
def test_sim_runs_the_hardware_driver_class_on_every_shipped_arm(arm: str) -> None:
    model = load_model(arm)
    kind = native_kind(model)
    expected = hardware_class("dynamixel" if kind == "generic" else kind)
    driver = open_driver(model, "sim")
    try:
        assert type(driver) is expected
        assert world_of(driver) is not None
    finally:
        driver.close()


@pytest.mark.parametrize(
    "arm, driver",
    [
        ("lynx6", "ssc32"),
        ("lynx6", "maestro"),
        ("al5d", "maestro"),
        ("openmanipulator_x", "dynamixel"),
        ("owi535", "owi535"),
    ],
)
def test_port_emu_runs_that_driver_on_a_simulated_device(arm: str, driver: str) -> None:
    opened = open_driver(load_model(arm), driver, "emu")
    try:
        assert type(opened) is hardware_class(driver)
        assert world_of(opened) is not None
    finally:
        opened.close()


def test_kinds() -> None:
    kinds = {arm: native_kind(load_model(arm)) for arm in shipped_models()}
    assert kinds == {
        "al5d": "ssc32",
        "lynx6": "ssc32",
        "openmanipulator_x": "dynamixel",
        "owi535": "owi535",
        "planar2": "generic",
        "puma560": "generic",
        "so100": "feetech",
        "so101": "feetech",
    }
    with pytest.raises(ValueError, match="unknown driver 'nope'; drivers are sim, owi535"):
        open_driver(load_model("lynx6"), "nope")
