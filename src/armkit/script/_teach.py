"""Teach and repeat: jog the arm with keys (000's basic mode), save poses, and write
what was taught and done as a script that ``armkit run`` replays.

Keys (one press, one step; 000's letters for the first four joints):
``i``/``k`` joint 1 +/-, ``j``/``u`` joint 2, ``f``/``r`` joint 3, ``d``/``e``
joint 4, ``g``/``t`` joint 5, ``h``/``y`` joint 6; ``w`` close and ``s`` open
the gripper; ``l``/``p`` light on/off (OWI); ``v`` save the pose (p1, p2, ...);
``+``/``-`` double/halve the step; ``?`` help; ``q`` or Enter leaves.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from datetime import datetime

import numpy as np
from numpy.typing import NDArray

from .._errors import ArmkitError
from ..arm import Arm
from ..connect import kinds_with

F64 = NDArray[np.float64]
JOG_KEYS = (("i", "k"), ("j", "u"), ("f", "r"), ("d", "e"), ("g", "t"), ("h", "y"))
OWI_STEP_S = 0.25  # one key press on a timed-motor arm: 000's 250 ms
JOG_HELP = (
    "jog keys: i/k j/u f/r d/e g/t h/y = joints 1..6 +/-, w close / s open gripper, "
    "l/p light, v save pose, +/- step, ? help, q or Enter leaves"
)


def joints_line(q: F64) -> str:
    """``joints a b c ...`` [deg] with 3 decimals (0.0005 deg)."""
    return "joints " + " ".join(f"{math.degrees(a):.3f}" for a in q)


def pose_now(arm: Arm) -> F64:
    """The arm's joint angles [rad], shape (dof,), clipped into the limits (a servo
    resting a hair past its limit still replays)."""
    return np.clip(arm.read(), arm.model.lower, arm.model.upper)


@dataclass
class Teaching:
    """What a shell session did, as script lines that replay it.

    Attributes:
        arm: the model's name or file (the script's ``arm`` line).
        start: joint angles when the session began [rad], shape (dof,).
        lines: the statements given, the taught poses and the jogs, in order.
        origin: where it was taught (the script's first comment).
        scene: the scene's name or file (the script's ``scene`` line), or None.
    """

    arm: str
    start: F64
    lines: list[str] = field(default_factory=list)
    origin: str = "the armkit shell"
    scene: str | None = None

    def record(self, text: str) -> None:
        """Add statements that ran (a line, or a block of lines)."""
        self.lines += [line.rstrip() for line in text.splitlines() if line.strip()]

    def save(self, name: str, q: F64) -> str:
        """Record pose ``name`` at ``q`` [rad]; returns its line."""
        line = f"pose {name} = {joints_line(q)}"
        self.lines.append(line)
        return line

    def script(self) -> str:
        """The session as a script: the arm and scene, where it started, then every line."""
        stamp = datetime.now().strftime("%Y-%m-%d %H:%M")
        head = [
            f"# taught in {self.origin} on {stamp}; replay with: armkit run FILE",
            f"arm {header_word(self.arm)}",
            *([f"scene {header_word(self.scene)}"] if self.scene is not None else []),
            f"{joints_line(self.start)}   # where the session started",
        ]
        return "\n".join(head + self.lines) + "\n"


def header_word(value: str) -> str:
    """``value`` as one word of an ``arm``/``scene`` line: as it is, or quoted when it has
    a space or a character that would end the word (``#``, ``=``, ``(``, ``)``, ``,``)."""
    if value and not any(c.isspace() or c in '#"=(),' for c in value):
        return value
    return '"' + value.replace('"', '\\"') + '"'


@dataclass
class Jog:
    """One jog session on ``arm``: keys in, messages out, the lines to record.

    Attributes:
        step: joint step per key [deg] (servo arms; timed arms run 250 ms).
        lines: what to record (``joints ...`` after moves, ``grip ...``, ``pose ...``).
        saved: names of the poses saved with ``v``.
    """

    arm: Arm
    step: float = 5.0
    lines: list[str] = field(default_factory=list)
    saved: list[tuple[str, F64]] = field(default_factory=list)
    _moved: bool = False

    def key(self, key: str, next_name: str) -> str | None:
        """Do what ``key`` asks; a message to show, or None."""
        for j, (plus, minus) in enumerate(JOG_KEYS[: self.arm.model.dof]):
            if key in (plus, minus):
                return self._turn(j, 1 if key == plus else -1)
        if key in ("w", "s"):
            return self._grip(key == "s")
        if key in ("l", "p"):
            return self._light(key == "l")
        if key == "v":
            return self._save(next_name)
        if key in ("+", "-"):
            self.step = min(45.0, self.step * 2) if key == "+" else max(0.25, self.step / 2)
            return f"step {self.step:g} deg"
        if key == "?":
            return JOG_HELP
        return f"unknown key {key!r}; ? for help"

    def finish(self) -> list[str]:
        """The lines of this jog session (the final pose if the arm moved since the last)."""
        self._flush()
        return self.lines

    def _turn(self, j: int, direction: int) -> str | None:
        name = self.arm.model.joint_names[j]
        try:
            if self.arm.moves == "timed":
                self.arm.run_motor(name, direction, OWI_STEP_S)
            else:
                self.arm.turn_by(name, direction * self.step)
        except (ArmkitError, ValueError) as exc:
            return f"{name}: {exc}"
        self._moved = True
        return None

    def _grip(self, open_: bool) -> str | None:
        g = self.arm.model.gripper
        self._flush()
        self.arm.grip((g.width_max if open_ else g.width_min) * 1000.0)
        self.lines.append("grip open" if open_ else "grip close")
        return None

    def _light(self, on: bool) -> str | None:
        if not self.arm.has_light:
            return f"{self.arm.model.name} has no light"
        self._flush()
        self.arm.set_light(on)
        self.lines.append("light on" if on else "light off")
        return None

    def _save(self, name: str) -> str:
        self._flush()
        q = pose_now(self.arm)
        self.saved.append((name, q))
        self.lines.append(f"pose {name} = {joints_line(q)}")
        return f"saved pose {name}"

    def _flush(self) -> None:
        if self._moved:
            self.lines.append(joints_line(pose_now(self.arm)))
            self._moved = False


def torque(arm: Arm, on: bool) -> None:
    """Torque on (``on``) or off on every servo of ``arm`` where its driver allows it
    (the Dynamixel's Torque Enable register): off, the arm can be moved by hand and
    ``read()`` still gives its true angles. ArmkitError, nothing sent, where it cannot."""
    # torque on where the servo is exists only where positions can be read while limp;
    # hobby servos can ``relax`` (no pulses) but never report where they are
    if arm.can_go_limp:
        arm.stiffen() if on else arm.relax()
        return
    raise ArmkitError(f"limp: {arm.model.name}: {_why_no_limp(arm)}; teach it with jog instead")


def _why_no_limp(arm: Arm) -> str:
    if arm.model.gripper.kind == "timed":
        return (
            "its DC motors have no torque off and no encoders (armkit only estimates "
            "its angles from time), so a pose moved by hand could not be read back"
        )
    on = "".join(
        f" on the {kind.title}" for kind in kinds_with("hobby") if kind.name == arm.controller
    )
    return (
        f"its hobby servos{on} report no position and take no torque-off command, "
        "so a pose moved by hand could not be read back"
    )
