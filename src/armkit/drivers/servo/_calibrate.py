"""Measure a servo arm's tables: step each servo to each table point, ask what it reads.

The person measures the real angle (or gripper opening) at every point of the
present table; the pulses are then re-interpolated so each table point gets the
pulse that really reaches it, and the unit's file is written atomically to the
user's config directory, where the driver finds it next time.
"""

from __future__ import annotations

from collections.abc import Callable
from datetime import UTC, datetime
from pathlib import Path

import numpy as np

from ..._errors import DeviceError, InputError
from ..._files import config_dir, write_atomic
from ...model import ArmModel
from ._arm import ServoArmDriver
from ._config import table_to_toml
from ._table import PULSE_MAX_US, PULSE_MIN_US, ServoCalibration

ASK_TRIES = 3
# How far a reading may be from the point it measures (deg for a joint, mm for the
# gripper): a servo off by more than this is not calibrated by a table but mounted
# wrongly, and a reading beyond it is a typo (-500 for 15).
MOST_OFF = {"deg": 45.0, "mm": 20.0}


def calibrate_servos(
    model: ArmModel, driver: object, ask: Callable[[str], str], say: Callable[[str], None]
) -> Path:
    """Calibrate every servo of ``driver`` and write ``<config dir>/<arm>-<driver>.toml``.

    Args:
        ask: shows a prompt, returns the person's answer (degrees or mm; empty = as shown).
        say: shows one line of information.

    Returns:
        The file written. The driver uses the new tables from now on.

    Raises:
        DeviceError: ``driver`` is not a servo driver (ssc32 or maestro).
        ValueError: an answer is not a number after 3 tries, or the measurements
            cannot make a table (not increasing, or needing a pulse beyond 500..2500 µs).
    """
    if not isinstance(driver, ServoArmDriver):
        raise DeviceError("calibrate needs a servo driver: --driver ssc32 or --driver maestro")
    say(f"Calibrating {model.name} on the {driver.bus.name}: each servo visits its table points.")
    say("Measure each position and type it; press Enter if it reads exactly as shown.")
    driver.move(model.home, speed=0.5)
    tables = [_calibrate_servo(driver, table, ask, say) for table in driver.tables]
    path = config_dir() / f"{model.name}-{driver.bus.name}.toml"
    write_atomic(path, _file_text(model, driver.bus.name, tables))
    driver.joints = tuple(tables[: len(driver.joints)])
    driver.grip_table = tables[-1] if driver.grip_table else None
    say(f"Wrote {path}")
    return path


def _calibrate_servo(
    driver: ServoArmDriver,
    table: ServoCalibration,
    ask: Callable[[str], str],
    say: Callable[[str], None],
) -> ServoCalibration:
    say(f"{table.name} (channel {table.channel}), range {table.range_text()}")
    measured = []
    for value, pulse in zip(table.values, table.pulses_us, strict=True):
        driver.move_servo(table.name, pulse)
        measured.append(_ask_value(table, value, pulse, ask))
    rest = driver.model.home[driver.joints.index(table)] if table in driver.joints else None
    if rest is not None:
        driver.move_servo(table.name, table.to_pulse(float(rest)))
    return _rebuild(table, measured)


def _ask_value(
    table: ServoCalibration, value: float, pulse: float, ask: Callable[[str], str]
) -> float:
    unit = "degrees" if table.unit == "deg" else "mm"
    shown = table.shown(value)
    prompt = f"  {table.name} at {pulse:.0f} µs should read {shown:.1f} {unit}; measured:"
    most = MOST_OFF["deg" if table.unit == "deg" else "mm"]
    for _ in range(ASK_TRIES):
        answer = ask(prompt).strip()
        if not answer:
            return value
        try:
            read = float(answer)
        except ValueError:
            prompt = f"  '{answer}' is not a number; {table.name} measured in {unit}:"
            continue
        if abs(read - shown) <= most:  # NaN and inf fail too
            return read / table.shown(1.0)
        prompt = (
            f"  {answer} {unit} is more than {most:g} {unit} from {shown:.1f} (a typo, or the "
            f"servo is mounted wrongly); {table.name} measured in {unit}:"
        )
    raise InputError(
        f"no reading within {most:g} {unit} of the point for {table.name} after {ASK_TRIES} "
        "tries; calibration stopped (nothing written)"
    )


def _rebuild(table: ServoCalibration, measured: list[float]) -> ServoCalibration:
    """The table whose points are ``table.values`` again, with the pulses that reach them
    according to the measurements (linear between measurements, extended past the ends)."""
    m, p = np.asarray(measured), np.asarray(table.pulses_us)
    if np.any(np.diff(m) <= 0):
        raise InputError(
            f"{table.name}: the measured values must increase from point to point "
            f"(got {', '.join(f'{table.shown(v):.1f}' for v in m)}); measure again"
        )
    pulses = [_interp_extended(v, m, p) for v in table.values]
    if not all(PULSE_MIN_US <= x <= PULSE_MAX_US for x in pulses):
        raise InputError(
            f"{table.name}: reaching {table.range_text()} would need pulses beyond "
            f"{PULSE_MIN_US:.0f}..{PULSE_MAX_US:.0f} µs; check the measurements or narrow the range"
        )
    return ServoCalibration(table.name, table.channel, table.values, tuple(pulses), table.unit)


def _interp_extended(x: float, xs: np.ndarray, ys: np.ndarray) -> float:
    """Piecewise-linear y(x) through (xs, ys), continued straight past both ends."""
    i = int(np.clip(np.searchsorted(xs, x) - 1, 0, len(xs) - 2))
    return float(ys[i] + (ys[i + 1] - ys[i]) * (x - xs[i]) / (xs[i + 1] - xs[i]))


def _file_text(model: ArmModel, driver: str, tables: list[ServoCalibration]) -> str:
    stamp = datetime.now(UTC).strftime("%Y-%m-%d %H:%M UTC")
    header = (
        f"# armkit servo calibration: {model.name} on {driver}, measured {stamp}.\n"
        "# Each servo: table points (degrees, or mm for the gripper) and the pulse [µs]\n"
        "# that reaches each one. Delete this file to go back to the ideal tables.\n"
    )
    return header + "".join("\n" + table_to_toml(t) for t in tables)
