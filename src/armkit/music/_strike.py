"""One strike: hover above the bar, a down stroke aimed below its top, contact
where the stick tip crosses the top, and a rebound back to the hover pose.

The stroke is aimed ``depth`` below the top so that the tip crosses it at speed
(a stroke ending on the top would touch it at zero speed and make no sound);
the rebound is commanded just after the contact so the stick never rests on
the bar. Loudness (MIDI velocity) sets the down stroke's speed and hover height: a
longer, faster stroke hits harder; a lower hover saves time and sounds softer
(seed 001 traded the two).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from .._errors import InputError
from ..kinematics import fk, ik, pitch_of
from ..model import ArmModel
from ._predict import JointProfile

F64 = NDArray[np.float64]
_STEP = 0.0005  # contact search grid [s]


@dataclass(frozen=True)
class StrikeParams:
    """How the arm strikes (SI units).

    Attributes:
        hover: hover of the stick tip above the struck surface for the loudest note [m];
            softer notes start lower (``min_hover`` at velocity 1).
        min_hover: lowest hover the planner may use when a note comes soon [m].
        levels: hover heights tried, from the note's own down to ``min_hover``.
        depth: how far below the top the softest down stroke is aimed [m]; louder
            strokes aim deeper, by up to the hover height (contact nearer the
            stroke's peak speed), never closer than 2 mm to the table.
        pitch: stick angle above the horizontal [rad] (-pi/3: 60 deg down), or None (free).
        soft, loud: down-stroke speed (fraction of the joints' maximum) for MIDI
            velocity 1 and 127; linear in between.
        travel_speed: speed fraction of the moves between bars and of the rebound.
        settle: time the stick waits at the hover pose before a down stroke [s].
        rebound_delay: time after the predicted contact at which the rebound starts [s].
        clearance: smallest height of the tip above the bar tops while travelling [m].
    """

    hover: float = 0.03
    min_hover: float = 0.01
    levels: int = 5
    depth: float = 0.008
    pitch: float | None = -math.pi / 3
    soft: float = 0.3
    loud: float = 1.0
    travel_speed: float = 1.0
    settle: float = 0.01
    rebound_delay: float = 0.002
    clearance: float = 0.003

    def __post_init__(self) -> None:
        if not 0.0 < self.min_hover <= self.hover <= 0.5:
            raise InputError(
                f"hover heights need 0 < min_hover <= hover <= 500 mm, got {self.min_hover}, {self.hover} m"
            )
        if not 0.0 < self.depth <= 0.05 or self.levels < 1:
            raise InputError(
                f"depth must be 0..50 mm and levels >= 1, got {self.depth} m, {self.levels}"
            )
        for name in ("soft", "loud", "travel_speed"):
            if not 0.0 < getattr(self, name) <= 1.0:
                raise InputError(
                    f"{name} is a fraction of the maximum speed in (0, 1], got {getattr(self, name)}"
                )
        if self.settle < 0 or self.rebound_delay < 0 or self.clearance < 0:
            raise InputError("settle, rebound_delay and clearance must be >= 0")

    def heights(self, velocity: int) -> F64:
        """Hover heights to try [m] for a MIDI ``velocity`` 1..127, highest first,
        shape (levels,): a loud note starts high (a longer, faster stroke)."""
        top = self.min_hover + _share(velocity) * (self.hover - self.min_hover)
        return np.linspace(top, self.min_hover, self.levels)

    def aim(self, velocity: int, height: float, room: float) -> float:
        """How far below the top [m] to aim a stroke from ``height`` [m] for a MIDI
        ``velocity``, with ``room`` [m] between the top and the table."""
        return max(min(self.depth + _share(velocity) * height, room - 0.002), 0.0005)

    def stroke_speed(self, velocity: int) -> float:
        """Down-stroke speed fraction for a MIDI ``velocity`` 1..127."""
        return self.soft + _share(velocity) * (self.loud - self.soft)


def _share(velocity: int) -> float:
    """MIDI velocity 1..127 -> 0..1."""
    return (min(max(velocity, 1), 127) - 1) / 126.0


@dataclass(frozen=True)
class StrikePoses:
    """Joint poses [rad], shape (dof,) each, for one struck point and hover height."""

    hover: F64
    through: F64
    height: float


def strike_poses(
    model: ArmModel, point: F64, height: float, depth: float, pitch: float | None, seed: F64
) -> StrikePoses:
    """Poses hovering ``height`` [m] above ``point`` and ``depth`` [m] below it (base
    frame [m]), the stick at one ``pitch`` [rad] (None: nearest ``seed``). Raises
    UnreachableError."""
    up = np.array([0.0, 0.0, 1.0])
    through = ik(model, point - depth * up, pitch, q_seed=seed).q
    held = float(pitch_of(fk(model, through)))
    hover = ik(model, point + height * up, held, q_seed=through).q
    return StrikePoses(hover, through, height)


def contact(model: ArmModel, profile: JointProfile, top_z: float) -> tuple[float, float] | None:
    """(time [s] from the stroke's start, tip speed [m/s]) where the tool point first
    goes below ``top_z`` [m, base frame]; None if it never does."""
    times = np.arange(0.0, profile.duration + _STEP, _STEP)
    z = fk(model, profile.sample(times)[0])[:, 2, 3] - top_z
    below = np.flatnonzero(z < 0.0)
    if below.size == 0 or below[0] == 0:
        return None
    lo, hi = float(times[below[0] - 1]), float(times[below[0]])
    for _ in range(30):  # bisection to well under a microsecond
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if _tip(model, profile, mid)[2] >= top_z else (lo, mid)
    h = 1e-5
    speed = float(
        np.linalg.norm(_tip(model, profile, hi + h) - _tip(model, profile, hi - h)) / (2 * h)
    )
    return hi, speed


def tip_path(model: ArmModel, profile: JointProfile, samples: int = 24) -> F64:
    """The tool point [m, base frame] at ``samples`` even times along ``profile``,
    shape (samples, 3)."""
    times = np.linspace(0.0, profile.duration, samples)
    path: F64 = fk(model, profile.sample(times)[0])[:, :3, 3]
    return path


def _tip(model: ArmModel, profile: JointProfile, t: float) -> F64:
    q = profile.sample(np.array([t]))[0][0]
    tip: F64 = fk(model, q)[:3, 3]
    return tip
