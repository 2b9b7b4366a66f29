"""Listening in the simulator: an ``armkit.sim`` Observer that hears the mallet.

After every simulation step (1 kHz of simulated time) the listener puts the
simulated arm's TRUE joint angles through forward kinematics (the arm with the
mallet as its tool) and checks whether the mallet's head has just gone down
through the top of a bar or a drum head, inside its outline. Each crossing is a
``Contact``: the time [s] it crossed (interpolated between the two steps), the
bar's note and the head's speed [m/s]; how long the head stayed below the top
(a mallet must rebound at once, not rest on the bar) is kept beside it. A new
contact on a surface needs the head to have come back up through the top first.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..kinematics import fk
from ..model import ArmModel
from ._layout import Bars, DrumLike, Instrument
from ._onsets import Contact

F64 = NDArray[np.float64]
REARM = 0.0005  # the head must rise this far above a top before it can strike it again [m]


@dataclass(frozen=True)
class Surface:
    """One struck surface, scene frame [m]: a bar (a rectangle ``half`` = (along the
    row, across it) half-sizes around ``centre`` with the row along ``along``) or a
    drum head (a disc of radius ``half[0]``)."""

    instrument: str
    note: int
    drum: bool
    centre: F64  # (3,): centre of the top
    half: tuple[float, float]
    along: F64  # (2,): unit vector along the row (bars)

    def under(self, xy: F64, margin: float = 0.0) -> bool:
        """True when the point ``xy`` [m], shape (2,), is over this surface (or within
        ``margin`` [m] of its edge)."""
        d = xy - self.centre[:2]
        if self.drum:
            return float(np.hypot(d[0], d[1])) <= self.half[0] + margin
        u = float(d @ self.along)
        v = float(d[1] * self.along[0] - d[0] * self.along[1])
        return abs(u) <= self.half[0] + margin and abs(v) <= self.half[1] + margin


def surfaces(layout: Sequence[Instrument]) -> tuple[Surface, ...]:
    """Every bar and drum head of ``layout`` (the scene's Xylophone and Drum), each
    bar at its own place, size and row direction."""
    out: list[Surface] = []
    for inst in layout:
        if isinstance(inst, Bars):
            out += _bars(inst)
        elif isinstance(inst, DrumLike):
            x, y = np.asarray(inst.position, dtype=np.float64)[:2]
            radius = float(getattr(inst, "radius", 0.05))
            centre = np.array([x, y, float(inst.top_z)])
            out.append(Surface(inst.name, inst.note, True, centre, (radius, radius), np.eye(2)[0]))
    return tuple(out)


def _bars(inst: Bars) -> list[Surface]:
    """The bars of ``inst``: sizes and row directions from the scene's Xylophone
    (``bar_size(note)``, ``bar_row(note)``); a plain ``Bars`` gets 40 x 10 mm bars
    along the line from its lowest bar to its highest."""
    tops = [np.asarray(inst.bar_top(n), dtype=np.float64) for n in inst.notes]
    line = tops[-1][:2] - tops[0][:2]
    row = float(np.arctan2(line[1], line[0]))
    size_of, row_of = getattr(inst, "bar_size", None), getattr(inst, "bar_row", None)
    out = []
    for note, top in zip(inst.notes, tops, strict=True):
        length, width = size_of(note) if callable(size_of) else (0.04, 0.01)
        angle = float(row_of(note)) if callable(row_of) else row
        along = np.array([np.cos(angle), np.sin(angle)])
        out.append(Surface(inst.name, note, False, top, (0.5 * width, 0.5 * length), along))
    return out


def height_over(found: Sequence[Surface], points: F64, margin: float) -> float:
    """Smallest height [m] of ``points`` (scene frame [m], shape (N, 3)) above the top
    of a surface they are over (within ``margin`` [m] of its edge); inf over none."""
    lowest = np.inf
    for p in points:
        for s in found:
            if s.under(p[:2], margin):
                lowest = min(lowest, float(p[2] - s.centre[2]))
    return float(lowest)


@dataclass
class Listener:
    """Observer (``armkit.sim.Observer``) recording every strike of one simulated arm.

    Args:
        model: the arm with the mallet as its tool (the tool point is the mallet's head).
        layout: the scene's instruments (scene frame).
        T_world_base: the arm's base in the scene frame, shape (4, 4).
        arm: the simulated arm's name in the world (None: the only one).

    Attributes:
        contacts: what was struck, world time [s].  dwell: seconds below the top, per contact.
    """

    model: ArmModel
    layout: Sequence[Instrument]
    T_world_base: ArrayLike = field(default_factory=lambda: np.eye(4))
    arm: str | None = None
    contacts: list[Contact] = field(default_factory=list)
    dwell: list[float] = field(default_factory=list)
    _surfaces: tuple[Surface, ...] = ()
    _last: tuple[float, F64] | None = None
    _below: tuple[Surface, float] | None = None  # the surface the head is under, since when

    def __post_init__(self) -> None:
        self._surfaces = surfaces(self.layout)
        self._T = np.asarray(self.T_world_base, dtype=np.float64)

    def on_step(self, world: object, t: float) -> None:
        """Called by the world after every step at ``t`` [s]."""
        q = world.arm(self.arm).q()  # type: ignore[attr-defined]
        tip = (self._T @ fk(self.model, q))[:3, 3]
        last, self._last = self._last, (t, tip)
        if last is None:
            return
        t0, p0 = last
        if self._below is not None:
            self._rise(t0, p0, t, tip)
            return
        for s in self._surfaces:
            top = float(s.centre[2])
            if p0[2] >= top > tip[2] and s.under(tip[:2]):
                share = (p0[2] - top) / (p0[2] - tip[2])
                when = t0 + share * (t - t0)
                speed = float(np.linalg.norm(tip - p0) / max(t - t0, 1e-9))
                self.contacts.append(Contact(when, s.instrument, s.note, speed, s.drum))
                self.dwell.append(0.0)
                self._below = (s, when)
                return

    def _rise(self, t0: float, p0: F64, t: float, tip: F64) -> None:
        """The head after a contact, from ``p0`` at ``t0`` to ``tip`` at ``t`` [s, m]: the
        dwell grows while it is below the top (to the interpolated crossing back up); the
        surface can be struck again once the head is ``REARM`` above it or off it."""
        surface, since = self._below  # type: ignore[misc]
        top = float(surface.centre[2])
        if p0[2] < top:
            share = 1.0 if tip[2] < top else (top - p0[2]) / (tip[2] - p0[2])
            self.dwell[-1] = t0 + share * (t - t0) - since
        if tip[2] > top + REARM or not surface.under(tip[:2]):
            self._below = None
