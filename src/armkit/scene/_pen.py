"""A pen the gripper can hold, and the stand it waits in (001's drawing task)."""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import NDArray

from .._inputs import mm
from .._primitives import RGB, Cylinder, Primitive
from .._primitives import pose as placed
from ._fields import Entry, entries
from ._object import Placed, Solid, Support
from ._rect import Rect

F64 = NDArray[np.float64]
STAND_COLOUR: RGB = (90, 90, 100)
PEN_COLOUR: RGB = (240, 200, 30)  # yellow
RELEASE_EPS = 0.2e-3  # [m]: as the clearance check's WIDTH_EPS for a held cube
PEN_KEYS = (
    "name",
    "length_mm",
    "holder_length_mm",
    "tip_offset_mm",
    "diameter_mm",
    "tool_length_mm",
)
STAND_KEYS = ("name", "position_mm", "pen", "pitch_deg")


@dataclass(frozen=True, eq=False)
class Pen:
    """A pen the gripper can hold (001's drawing task).

    Attributes:
        length: the pen's length [m].
        holder_length: how much of it stands inside its stand [m].
        tip_offset: from the gripper's tool point to the pen's tip while held [m]:
            the tool gets this much longer.
        diameter: where the jaws close on it (its holder) [m]: the grip width.
        tool_lengths: (arm name, tool length [m]) pairs: the tool length while held
            on that arm, from its last joint frame to the tip (001's pen holder on
            the OpenManipulator-X: 0.116 m); other arms: their own + ``tip_offset``.
    """

    name: str
    length: float
    holder_length: float
    tip_offset: float
    diameter: float = 0.024
    tool_lengths: tuple[tuple[str, float], ...] = ()

    def tool_length(self, arm: str, own: float) -> float:
        """The tool length [m] of arm ``arm`` holding this pen (``own``: its own [m])."""
        return dict(self.tool_lengths).get(arm, own + self.tip_offset)

    def solids(self) -> tuple[Solid, ...]:
        """None: the gripper takes the pen on purpose."""
        return ()

    def supports(self, foot: Rect) -> tuple[Support, ...]:
        """None: nothing rests on a pen."""
        return ()

    def listed(self, scene: Placed) -> tuple[str, str]:
        """Its length, how much of it its stand holds, where its tip is."""
        return "pens", (
            f"{self.name}: {self.length * 1000:.1f} mm long, {self.holder_length * 1000:.1f} mm "
            f"in its stand, tip {self.tip_offset * 1000:.1f} mm beyond the tool point"
        )

    def primitives(self, scene: Placed) -> list[Primitive]:
        """None of its own: its stand draws it standing in it."""
        return []


@dataclass(frozen=True)
class HeldTool:
    """A tool in the gripper (a pen, a mallet): what a plan's tool point is while it is
    held, and what a simulated arm keeps with its joints between processes.

    Attributes:
        name: the scene's pen it is (``"pen"``, ``"mallet"``).
        tool_length: the arm's tool length while it is held, from its last joint frame
            to the tool's tip [m] (``ArmModel.with_tool_length``).
        width: where the jaws hold it [m]: opening them wider by more than the margin
            lets it go (``released_by``).
    """

    name: str
    tool_length: float
    width: float

    def released_by(self, width: float) -> bool:
        """Whether opening the jaws to ``width`` [m] lets it go (as ``Held.released_by``)."""
        return width > self.width + RELEASE_EPS


@dataclass(frozen=True, eq=False)
class PenStand:
    """Where a pen stands when not held.

    Attributes:
        position: centre of the stand's opening [m], shape (3,).
        pen: the name of the pen in it.
        pitch: the pen's axis from the opening to its tip, above the horizontal,
            in the vertical plane through the arm's base [rad]: -pi/2 upright, tip
            down (a pot); 0 lying, tip pointing away from the arm (a cradle).
    """

    name: str
    position: F64
    pen: str
    pitch: float = -math.pi / 2

    def solids(self) -> tuple[Solid, ...]:
        """None: the gripper reaches into it for the pen."""
        return ()

    def supports(self, foot: Rect) -> tuple[Support, ...]:
        """None: nothing rests on a pen stand."""
        return ()

    def listed(self, scene: Placed) -> tuple[str, str]:
        """Where it stands and the pen it holds."""
        return "pen stands", f"{self.name}: {mm(self.position)}, holds {self.pen}"

    def primitives(self, scene: Placed) -> list[Primitive]:
        """The stand and the pen standing in it."""
        pen = next((p for p in _pens(scene) if p.name == self.pen), None)
        length = pen.length if pen is not None else 0.12
        base = placed(self.position - np.array([0.0, 0.0, 0.015]))
        tip = self.position + np.array([0.0, 0.0, length / 2 - (pen.holder_length if pen else 0.0)])
        return [
            Cylinder(f"/scene/{self.name}", 0.015, 0.03, base, STAND_COLOUR),
            Cylinder(f"/scene/{self.pen}", 0.005, length, placed(tip), PEN_COLOUR),
        ]


def _pens(scene: Placed) -> list[Pen]:
    return [obj for obj in scene.objects() if isinstance(obj, Pen)]


def load_pens(path: Path, data: dict[str, Any], scene: Placed) -> tuple[Pen, ...]:
    """``[[pens]]``: each shorter than its holder, with tool lengths per arm."""
    return tuple(_pen(e) for e in entries(path, data, "pens", PEN_KEYS))


def load_pen_stands(path: Path, data: dict[str, Any], scene: Placed) -> tuple[PenStand, ...]:
    """``[[pen_stands]]``: each holding a pen of ``[[pens]]``."""
    pens = {p.name for p in _pens(scene)}
    return tuple(_pen_stand(e, pens) for e in entries(path, data, "pen_stands", STAND_KEYS))


def _pen(e: Entry) -> Pen:
    length, holder = e.positive_mm("length_mm"), e.positive_mm("holder_length_mm")
    if holder >= length:
        raise e.fail("holder_length_mm", f"must be < length_mm ({length * 1000:g})")
    diameter = e.positive_mm("diameter_mm", 24.0)
    lengths = e.data.get("tool_length_mm", {})
    if not isinstance(lengths, dict) or not all(
        isinstance(v, int | float) and not isinstance(v, bool) and 0 < v < 1000
        for v in lengths.values()
    ):
        raise e.fail("tool_length_mm", "must be a table of arm = length in mm (0..1000)")
    tools = tuple((str(k), float(v) / 1000.0) for k, v in lengths.items())
    return Pen(e.name(), length, holder, e.mm("tip_offset_mm"), diameter, tools)


def _pen_stand(e: Entry, pens: set[str]) -> PenStand:
    pen = e.text("pen")
    if pen not in pens:
        raise e.fail(
            "pen", f"no pen {pen!r} in [[pens]]; pens: {', '.join(sorted(pens)) or 'none'}"
        )
    pitch = e.deg("pitch_deg", -90.0)
    if not -np.pi / 2 - 1e-9 <= pitch <= 1e-9:
        raise e.fail("pitch_deg", "must be -90 (upright) .. 0 (lying)")
    return PenStand(e.name(), e.point_mm("position_mm"), pen, pitch)
