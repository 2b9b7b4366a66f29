"""The registry of driver kinds (``armkit.connect.driver_kinds()``): every kind has every
part, and every place that knows the kinds reads the registry, so that a kind added by
one entry is found by ``armkit --help``, ``--driver``, ``emulate``, ``calibrate`` and
the script language, with no table elsewhere to forget."""

from __future__ import annotations

import dataclasses
import io
from collections.abc import Iterator
from contextlib import redirect_stderr, redirect_stdout
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from armkit import ArmkitError
from armkit.cli import main
from armkit.connect import (
    CalibrationRoutine,
    DriverKind,
    driver_kind,
    driver_kinds,
    emulate,
    open_driver,
    world_of,
)
from armkit.connect import _kinds as registry
from armkit.model import SECTIONS, load_model, shipped_models
from armkit.script import Source, check_source


def _armkit(*argv: str) -> tuple[int, str]:
    out = io.StringIO()
    with redirect_stdout(out), redirect_stderr(out):
        code = main(list(argv))
    return code, " ".join(out.getvalue().split())  # as read, not as wrapped


def _shipped_arm_of(kind: DriverKind) -> str:
    """A shipped arm whose model file has ``kind``'s section (every kind needs one)."""
    arms = [arm for arm in shipped_models() if kind.section.name in load_model(arm).drivers]
    assert arms, f"no shipped arm has a [drivers.{kind.section.name}] table for {kind.name}"
    return arms[0]


def test_kinds_have_different_names_and_their_sections_are_the_model_files() -> None:
    names = [kind.name for kind in driver_kinds()]
    assert len(set(names)) == len(names) and "sim" not in names
    assert {kind.section for kind in driver_kinds()} == set(SECTIONS)


@pytest.mark.parametrize("kind", driver_kinds(), ids=lambda kind: kind.name)
def test_every_kind_has_every_part(kind: DriverKind) -> None:
    assert kind.device and kind.title and kind.traits
    assert kind.traits <= {"timed", "hobby", "smart"} and kind.port in ("serial", "usb")
    assert callable(kind.open) and callable(kind.simulate) and callable(kind.forecast)
    # a serial device can be served on a pseudo-terminal; a USB board cannot
    assert (kind.emulate is not None) == (kind.port == "serial")
    # a kind whose unit cannot report its position is calibrated by a person
    if kind.traits & {"timed", "hobby"}:
        assert isinstance(kind.calibrate, CalibrationRoutine) and callable(kind.calibrate.run)
    # a hobby-servo controller takes one raw pulse (armkit servo)
    assert (kind.pulses is not None) == ("hobby" in kind.traits)


@pytest.mark.parametrize("kind", driver_kinds(), ids=lambda kind: kind.name)
def test_every_kind_runs_its_driver_on_its_simulated_device(kind: DriverKind) -> None:
    model = load_model(_shipped_arm_of(kind))
    driver = open_driver(model, kind.name, "emu")
    try:
        assert world_of(driver) is not None
        assert driver.read().shape == (model.dof,)
    finally:
        driver.close()


@pytest.mark.parametrize("kind", driver_kinds(), ids=lambda kind: kind.name)
def test_every_kind_forecasts_without_a_device_as_its_driver_does(kind: DriverKind) -> None:
    # ``armkit check`` times a script with the kind's forecasts; ``Arm`` with its driver's
    model = load_model(_shipped_arm_of(kind))
    alone = kind.forecast(model, None)
    driver = open_driver(model, kind.name, "emu")
    try:
        q0, q1 = model.home, model.home + np.radians(10.0)
        a, b = alone.forecast(q0, q1), driver.forecast(q0, q1)
        assert (a.seconds, a.motor_s) == pytest.approx((b.seconds, b.motor_s))
        np.testing.assert_allclose(a.q, b.q)
        g = model.gripper
        closing = (g.width_max, g.width_min)
        assert alone.forecast_grip(*closing) == pytest.approx(driver.forecast_grip(*closing))
        assert alone.moves == driver.moves and {driver.moves} == set(kind.traits)
    finally:
        driver.close()


@pytest.mark.parametrize("kind", driver_kinds(), ids=lambda kind: kind.name)
def test_every_kind_opens_real_hardware_only_where_there_is_some(kind: DriverKind) -> None:
    model = load_model(_shipped_arm_of(kind))
    port = "/dev/armkit-no-such-port" if kind.port == "serial" else "armkit-no-such-unit"
    with pytest.raises(ArmkitError):
        kind.open(model, port).close()


@pytest.mark.parametrize("kind", [k for k in driver_kinds() if k.emulate], ids=lambda k: k.name)
def test_every_serial_kind_is_emulated_alone_and_driving_its_arm(kind: DriverKind) -> None:
    for model in (None, load_model(_shipped_arm_of(kind))):
        emulator = emulate(kind.name, model)
        try:
            assert Path(emulator.port).exists()
        finally:
            emulator.close()


# A kind added by one entry: an SSC-32 clone that reads the SSC-32's section.
CALIBRATED: list[tuple[str, str]] = []


def _calibrate_clone(model: Any, driver: Any, ask: Any, say: Any) -> Path:
    CALIBRATED.append((model.name, type(driver).__name__))
    return Path("clone.toml")


SIMULATED: list[str] = []  # the models the clone's simulated device was built for


@pytest.fixture
def clone() -> Iterator[DriverKind]:
    ssc32 = driver_kind("ssc32")

    def simulate_clone(model: Any, world: Any, keep: Any, opened: Any) -> Any:
        SIMULATED.append(model.name)
        return ssc32.simulate(model, world, keep, opened)

    added = dataclasses.replace(
        ssc32,
        name="clone32",
        device="an SSC-32 clone",
        title="SSC-32 clone",
        simulate=simulate_clone,
        calibrate=CalibrationRoutine(_calibrate_clone),
    )
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(registry, "KINDS", (*registry.KINDS, added))
        yield added
    CALIBRATED.clear()
    SIMULATED.clear()


def test_a_kind_added_by_one_entry_is_in_the_help_and_the_driver_choices(
    clone: DriverKind,
) -> None:
    code, text = _armkit("--help")
    kinds = "sim (default), owi535, ssc32, maestro, dynamixel, feetech, clone32"
    assert code == 0 and kinds in text
    assert "dynamixel, feetech and clone32" in text  # --port: the serial kinds
    code, text = _armkit("--arm", "lynx6", "--driver", "clone32", "--port", "emu", "where")
    assert code == 0 and "gripper at" in text
    code, text = _armkit("--arm", "lynx6", "--driver", "clone33", "where")
    kinds = "drivers are sim, owi535, ssc32, maestro, dynamixel, feetech, clone32"
    assert code == 2 and kinds in text


def test_a_kind_added_by_one_entry_is_emulated(clone: DriverKind) -> None:
    code, text = _armkit("--help")
    assert (
        code == 0
        and "serve a simulated SSC-32, Maestro, Dynamixel bus, Feetech bus or SSC-32 clone" in text
    )
    code, text = _armkit("emulate", "--help")
    assert code == 0 and "{ssc32,maestro,dynamixel,feetech,clone32}" in text
    assert "--driver ssc32, maestro, dynamixel, feetech or clone32" in text
    emulator = emulate("clone32", load_model("lynx6"))  # what 'armkit emulate clone32' serves
    try:
        assert Path(emulator.port).exists()
    finally:
        emulator.close()


def test_a_kind_added_by_one_entry_takes_a_raw_pulse_on_its_own_controller(
    clone: DriverKind,
) -> None:
    # the clone is an SSC-32: channel 30 (a Maestro has 0..23) and its QP read-back
    code, text = _armkit("--driver", "clone32", "--port", "emu", "servo", "30", "1200")
    assert code == 0 and "channel 30: sent 1200 µs, controller reports 1200 µs" in text, text


def test_a_kind_added_by_one_entry_is_calibrated_by_its_own_routine(clone: DriverKind) -> None:
    code, text = _armkit("--arm", "lynx6", "--driver", "clone32", "--port", "emu", "calibrate")
    assert code == 0, text
    assert CALIBRATED == [("lynx6", "ServoArmDriver")] and "wrote clone.toml" in text
    code, text = _armkit("--arm", "openmanipulator_x", "--driver", "dynamixel", "calibrate")
    assert (
        code == 2
        and "--driver owi535, ssc32, maestro, feetech, clone32 (or sim on the owi535 or feetech)"
        in text
    )


def test_a_kind_added_by_one_entry_is_a_driver_of_the_script_language(clone: DriverKind) -> None:
    def errors(text: str) -> list[str]:
        result = check_source(Source("job.arm", text), model=load_model("lynx6"))
        return [d.message for d in result.diagnostics if d.severity == "error"]

    assert errors("driver clone32\nhome\n") == []
    assert "did you mean 'clone32'" in errors("driver clone23\nhome\n")[0]


def test_a_script_naming_a_kind_added_by_one_entry_runs_on_it(
    clone: DriverKind, tmp_path: Path
) -> None:
    script = tmp_path / "job.arm"
    script.write_text("arm lynx6\ndriver clone32 port emu\nhome\nmove xyz 200 0 100\n")
    code, text = _armkit("run", str(script))
    assert code == 0 and f"done: {script} in" in text, text
    assert SIMULATED == ["lynx6"]  # the clone's own part opened the arm the script ran on
    code, text = _armkit("check", str(script))
    assert code == 0 and "ok for lynx6" in text, text
