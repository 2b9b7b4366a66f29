"""Keyboard mode (000's 'basic mode'): one key = one 250 ms move, no Enter,
with the estimated angles and gripper position on one live status line."""

from __future__ import annotations

import math
import os
import sys
from collections.abc import Callable, Iterator
from typing import TextIO

from ..._terminal import cbreak
from ...kinematics import fk
from ._driver import TimedDriver

# key -> (motor, direction); 000's letters
MOTION_KEYS: dict[str, tuple[str, int]] = {
    "e": ("wrist", -1), "d": ("wrist", +1), "r": ("elbow", -1), "f": ("elbow", +1),
    "u": ("shoulder", -1), "j": ("shoulder", +1), "k": ("base", -1), "i": ("base", +1),
}  # fmt: skip
HELP = """keys: w close / s open gripper   e/d wrist up/down   r/f elbow back/forward
      u/j shoulder back/forward   k/i base left/right   l/p light on/off   ? help   q quit"""


def handle_key(driver: TimedDriver, key: str, step_s: float) -> str | None:
    """Do what ``key`` asks; returns a message to show, or None. 'q' is not handled here."""
    if key in MOTION_KEYS:
        name, direction = MOTION_KEYS[key]
        return _turn(driver, name, direction, step_s)
    actions: dict[str, Callable[[], None]] = {
        "w": lambda: driver.open_gripper(False),
        "s": lambda: driver.open_gripper(True),
        "l": lambda: driver.set_light(True),
        "p": lambda: driver.set_light(False),
    }
    if key in actions:
        actions[key]()
        return None
    if key == "?":
        return HELP
    return f"unknown key {key!r}; press ? for help"


def _turn(driver: TimedDriver, name: str, direction: int, step_s: float) -> str | None:
    j = driver.model.joint_index(name)
    limit = driver.timing.upper[j] if direction > 0 else driver.timing.lower[j]
    if abs(driver.read()[j] - limit) < 1e-6:
        return f"{name} is at its limit ({math.degrees(limit):+.0f} deg); turn it the other way"
    driver.turn_for(name, direction, step_s)
    return None


def status_line(driver: TimedDriver) -> str:
    """Estimated angles [deg], gripper point [mm], gripper, light, certainty."""
    q = driver.read()
    angles = " ".join(
        f"{n[:2]}{round(math.degrees(a)) + 0:+5d}"
        for n, a in zip(driver.joint_names, q, strict=True)
    )
    x, y, z = (round(float(v)) + 0 for v in fk(driver.model, q)[:3, 3] * 1000)  # no "-0"
    st = driver.state
    flags = f"grip {st.gripper} light {'on' if st.light else 'off'}"
    sure = f"UNCERTAIN: {st.reason} (rehome)" if st.uncertain else "certain"
    return f"{angles} | xyz {x:4d} {y:4d} {z:4d} mm | {flags} | {sure}"


def run_keys(driver: TimedDriver, stdin: TextIO = sys.stdin, out: TextIO = sys.stdout) -> int:
    """The keyboard loop until 'q' (or end of input). The terminal is restored on every exit."""
    step_s = driver.config.teleop_step_ms / 1000.0
    out.write(HELP + "\n")
    with cbreak(stdin):
        _show(out, status_line(driver))
        for key in _keys(stdin):
            if key in ("q", "\x04"):
                break
            message = handle_key(driver, key, step_s)
            if message:
                out.write("\r\x1b[K" + message + "\n")
            _show(out, status_line(driver))
    out.write("\n")
    out.flush()
    return 0


def _show(out: TextIO, line: str) -> None:
    out.write("\r\x1b[K" + line)
    out.flush()


def _keys(stdin: TextIO) -> Iterator[str]:
    fd = stdin.fileno()
    while True:
        data = os.read(fd, 1)
        if not data:
            return
        yield data.decode("latin-1")
