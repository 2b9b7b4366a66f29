"""Calibration: guide a person through timing each joint limit to limit, up
and down, several runs, then short pulses; fit the timing model; write the
unit's state file. On the simulator an automatic operator answers instead of
a person (``armkit.sim.owi_operator``), so benchmarks use the same routine."""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import replace
from pathlib import Path

import numpy as np

from ..._errors import InputError
from ...model import ArmModel
from ._config import default_timing
from ._driver import TimedDriver
from ._fit import Traverse, fit_timing
from ._rehome import rehome

Ask = Callable[[str], str]
Say = Callable[[str], None]


def calibrate_owi535(
    model: ArmModel,
    driver: TimedDriver,
    ask: Ask,
    say: Say,
    *,
    runs: int = 2,
    pulses: int = 6,
    pulse_s: float = 0.5,
) -> Path:
    """Calibrate the unit behind ``driver`` (an OWI driver for ``model``) and save it;
    returns the state file. Starts from the model file's default timing (the unit's
    limits kept) and counts battery use from now: fresh batteries first.

    Args:
        ask: shows a prompt and returns the person's answer (blocks until Enter).
        say: shows a line of text.
        runs: timed traverses per joint, pose and direction.
        pulses, pulse_s: short pulses [s] per pulse traverse (reveal slip and coast).
    """
    _begin(model, driver, ask, say)
    measured: list[Traverse] = []
    for name in driver.config.calibration_order:
        runs_of_joint = _calibrate_joint(driver, name, ask, say, runs, pulses, pulse_s)
        driver.set_state(driver.state.with_(timing=fit_timing(driver.timing, runs_of_joint)))
        measured += runs_of_joint
    say("the base once more, to measure how fast the batteries fade.")
    measured += _calibrate_joint(driver, "base", ask, say, 1, 0, pulse_s)
    timing = fit_timing(driver.timing, measured)
    extra = dict(driver.state.extra, traverse_s=_mean_traverses(driver, measured))
    driver.set_state(driver.state.with_(timing=timing, calibrated=True, extra=extra))
    driver.move_report(driver.model.home, table=False)
    _report(driver, say)
    return driver.path


def _begin(model: ArmModel, driver: TimedDriver, ask: Ask, say: Say) -> None:
    """Instructions, the model file's default timing (the unit's limits kept), battery
    use counted from now, and a re-homing so every angle is known."""
    if driver.model is not model and driver.model.name != model.name:
        raise InputError(f"the driver drives {driver.model.name!r}, not {model.name!r}")
    say(
        "Calibration: each joint is timed between its limits. Stand the arm at the edge "
        "of the table (it reaches below the top) and keep hands and objects clear."
    )
    ask("Put in fresh batteries, clear the space around the arm, then press Enter.")
    start = replace(default_timing(model), lower=driver.timing.lower, upper=driver.timing.upper)
    driver.set_state(driver.state.with_(timing=start, motor_s=0.0, calibrated=False))
    rehome(driver, say)


def _calibrate_joint(
    driver: TimedDriver, name: str, ask: Ask, say: Say, runs: int, pulses: int, pulse_s: float
) -> list[Traverse]:
    j = driver.model.joint_index(name)
    out: list[Traverse] = []
    for n, pose in enumerate(driver.config.calibration_pose[name]):
        for other, rest in pose.items():  # a limit's name, or an angle [deg] in the file
            _rest(driver, other, rest if isinstance(rest, str) else math.radians(rest), say)
        say(f"{name}: running it to its lower limit.")
        driver.drive_to_limit(name, -1, _waiter(ask, name, "lower"))
        for k in range(runs):
            say(f"{name}, pose {n + 1}: run {k + 1} of {runs}.")
            for direction, limit in ((1, "upper"), (-1, "lower")):
                out.append(_timed(driver, j, direction, _waiter(ask, name, limit)))
    for direction, limit in ((1, "upper"), (-1, "lower")) if pulses else ():
        say(f"{name}: {pulses} short pulses, then on to the {limit} limit.")
        out.append(_pulsed(driver, j, direction, pulses, pulse_s, _waiter(ask, name, limit)))
    return out


def _rest(driver: TimedDriver, name: str, rest: str | float, say: Say) -> None:
    """Put ``name`` against a limit ("lower"/"upper") or at an angle [rad] reached from one."""
    if isinstance(rest, str):
        say(f"the {name} goes against its {rest} limit.")
        driver.drive_to_limit(name, 1 if rest == "upper" else -1)
        return
    j = driver.model.joint_index(name)
    nearest = -1 if rest - driver.timing.lower[j] < driver.timing.upper[j] - rest else 1
    say(f"the {name} goes to {math.degrees(rest):.0f} deg, from a limit.")
    driver.drive_to_limit(name, nearest)
    driver.turn_to(name, rest)


def _timed(driver: TimedDriver, j: int, direction: int, wait: Callable[[], object]) -> Traverse:
    pose, used = tuple(float(a) for a in driver.read()), driver.state.motor_s
    seconds = driver.drive_to_limit(driver.joint_names[j], direction, wait)
    return Traverse(j, direction, seconds, pose, used)


def _pulsed(
    driver: TimedDriver,
    j: int,
    direction: int,
    pulses: int,
    pulse_s: float,
    wait: Callable[[], object],
) -> Traverse:
    pose, used = tuple(float(a) for a in driver.read()), driver.state.motor_s
    name = driver.joint_names[j]
    for _ in range(pulses):
        driver.turn_for(name, direction, pulse_s)
        driver.clock.sleep(0.3)  # let it settle
    seconds = driver.drive_to_limit(name, direction, wait)
    return Traverse(j, direction, seconds, pose, used, pulses, pulse_s)


def _waiter(ask: Ask, name: str, limit: str) -> Callable[[], object]:
    return lambda: ask(
        f"Press Enter the moment the {name} reaches its {limit} limit (it stops turning)."
    )


def _mean_traverses(driver: TimedDriver, measured: list[Traverse]) -> dict[str, float]:
    """Mean limit-to-limit time [s] per joint, both directions: 000's single number."""
    out = {}
    for j, name in enumerate(driver.joint_names):
        times = [r.seconds for r in measured if r.joint == j and r.pulses == 0]
        if times:
            out[name] = float(np.mean(times))
    return out


def _report(driver: TimedDriver, say: Say) -> None:
    for name, jt in zip(driver.joint_names, driver.timing.joints, strict=True):
        r = [f"{math.degrees(x):.1f}" for x in jt.rates]
        rates = f"fwd {r[0]}/{r[1]} back {r[2]}/{r[3]}" if jt.gravity else f"fwd {r[0]} back {r[2]}"
        kind = " (lowering/lifting)" if jt.gravity else ""
        over = "/".join(f"{math.degrees(o):.1f}" for o in jt.overshoot)
        say(f"{name:9s} {rates} deg/s{kind}, extra travel per move {over} deg")
    say(f"battery: speed falls {driver.timing.drain * 3600 * 100:.0f}% per hour of motor time")
    say(f"saved {driver.path}")
