"""Fitting a drawing onto a sheet (scale, margin, rotation, keep aspect) and
cutting what lies outside the sheet's printable area.

Sheet coordinates: u along the sheet's width, v along its height, both [m],
origin at a corner, the drawing upright when v points up the page. The fit is
a 2-D affine map (3, 3) from the drawing's metres (y up) into (u, v).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ._errors import DrawingError

F64 = NDArray[np.float64]


@dataclass(frozen=True)
class Fit:
    """How a drawing goes onto the sheet.

    The default is the file's real size (its units, ``viewBox`` and
    ``width``/``height``), centred on the sheet, as AxiDraw and vpype keep a
    file's size; ``Fit.to_sheet()`` scales it to fill the sheet instead.

    Attributes:
        scale: None: as large as fits inside the margins; else this factor
            (1.0 = the file's real size, the default).
        margin: clear border on every side [m]; nothing is drawn there.
        rotation: turn the drawing by this much [rad], counter-clockwise.
        keep_aspect: False stretches the drawing to fill the printable area
            (only with ``scale`` None).
        center: True centres the drawing on the sheet; False keeps its own
            coordinates as sheet coordinates (G-code made for this sheet,
            shapes placed in u, v).
    """

    scale: float | None = 1.0
    margin: float = 0.010
    rotation: float = 0.0
    keep_aspect: bool = True
    center: bool = True

    def __post_init__(self) -> None:
        if self.scale is not None and not (math.isfinite(self.scale) and self.scale > 0):
            raise DrawingError(f"scale must be > 0 (1 = real size), got {self.scale}")
        if not (math.isfinite(self.margin) and self.margin >= 0):
            raise DrawingError(f"margin must be >= 0 m, got {self.margin}")
        if not math.isfinite(self.rotation):
            raise DrawingError(f"rotation must be finite, got {self.rotation}")
        if not self.keep_aspect and self.scale is not None:
            raise DrawingError("keep_aspect=False stretches to fit: give no scale with it")

    @classmethod
    def to_sheet(cls, margin: float = 0.010, rotation: float = 0.0) -> Fit:
        """Scaled to fill the sheet inside the margins, aspect kept (``--fit``)."""
        return cls(scale=None, margin=margin, rotation=rotation)

    @classmethod
    def as_is(cls, margin: float = 0.0) -> Fit:
        """Real size, where the drawing's coordinates say (G-code for this sheet, shapes)."""
        return cls(scale=1.0, margin=margin, center=False)


def as_fit(fit: Fit | bool | None) -> Fit:
    """A job's ``fit`` argument as a ``Fit``: None or False: the file's real size,
    centred on the sheet; True: scaled to the sheet (``--fit``, the script's ``fit``)."""
    if isinstance(fit, Fit):
        return fit
    if fit is None or fit is False:
        return Fit()
    if fit is True:
        return Fit.to_sheet()
    raise DrawingError(f"fit must be True, False or a Fit, got {fit!r}")


def fit_transform(strokes: Sequence[F64], size: tuple[float, float], fit: Fit) -> F64:
    """The map (3, 3) from drawing metres to sheet (u, v) [m] for a sheet of
    ``size`` (width, height) [m]."""
    w, h = size
    room = np.array([w - 2 * fit.margin, h - 2 * fit.margin])
    if not np.all(room > 0):
        raise DrawingError(
            f"a margin of {fit.margin * 1e3:g} mm leaves no room on a "
            f"{w * 1e3:g} x {h * 1e3:g} mm sheet; use a smaller margin"
        )
    c, s = math.cos(fit.rotation), math.sin(fit.rotation)
    R = np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
    pts = np.vstack(strokes) @ R[:2, :2].T
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    k = _scales(hi - lo, room, fit)
    if fit.center and fit.scale is not None:
        _check_fits(k * (hi - lo), room, w, h, fit.margin)
    S = np.diag([k[0], k[1], 1.0])
    M: F64 = S @ R
    if fit.center:
        M[:2, 2] = np.array([w, h]) / 2 - k * (lo + hi) / 2
    return M


def _check_fits(extent: F64, room: F64, w: float, h: float, margin: float) -> None:
    """DrawingError with the drawing's size if ``extent`` (2,) [m] exceeds ``room``."""
    if np.all(extent <= room + 1e-9):
        return
    dw, dh = extent * 1e3
    raise DrawingError(
        f"the drawing is {dw:.1f} x {dh:.1f} mm, more than the {room[0] * 1e3:g} x "
        f"{room[1] * 1e3:g} mm inside the {margin * 1e3:g} mm margins of the "
        f"{w * 1e3:g} x {h * 1e3:g} mm sheet; scale it to the sheet with --fit "
        "(script: fit)"
    )


def _scales(extent: F64, room: F64, fit: Fit) -> F64:
    """Scale along u and v."""
    if fit.scale is not None:
        return np.array([fit.scale, fit.scale])
    with np.errstate(divide="ignore"):
        k = np.where(extent > 0, room / np.maximum(extent, 1e-300), np.inf)
    if not np.any(np.isfinite(k)):
        return np.ones(2)  # a dot: any scale fits
    if fit.keep_aspect:
        return np.full(2, np.min(k))
    return np.where(np.isfinite(k), k, np.min(k))


def apply(M: F64, strokes: Sequence[F64]) -> list[F64]:
    """Strokes mapped by the affine map ``M`` (3, 3)."""
    return [s @ M[:2, :2].T + M[:2, 2] for s in strokes]


def clip_to_box(strokes: Sequence[F64], lo: F64, hi: F64) -> list[F64]:
    """The parts of the strokes inside the box [lo, hi] (2,) each [m]
    (Liang–Barsky on every segment at once); a stroke may split in several."""
    out: list[F64] = []
    for s in strokes:
        if np.all(s >= lo) and np.all(s <= hi):
            out.append(s)
        elif len(s) >= 2:
            out.extend(_clip_one(s, lo, hi))
    return out


def _clip_one(s: F64, lo: F64, hi: F64) -> list[F64]:
    p0, d = s[:-1], np.diff(s, axis=0)
    t0, t1 = np.zeros(len(d)), np.ones(len(d))
    for axis in (0, 1):
        for q, sign in ((p0[:, axis] - lo[axis], -1.0), (hi[axis] - p0[:, axis], 1.0)):
            p = sign * d[:, axis]
            with np.errstate(divide="ignore", invalid="ignore"):
                r = q / p
            t0 = np.where(p < 0, np.maximum(t0, r), t0)
            t1 = np.where(p > 0, np.minimum(t1, r), t1)
            t1 = np.where((p == 0) & (q < 0), -1.0, t1)
    seen = t0 <= t1
    a, b = p0 + t0[:, None] * d, p0 + t1[:, None] * d
    joined = np.zeros(len(d), dtype=bool)
    joined[1:] = seen[:-1] & (t1[:-1] >= 1.0) & (t0[1:] <= 0.0)
    idx = np.flatnonzero(seen)
    first = ~joined[idx]  # this visible piece starts a new run
    at = np.cumsum(1 + first) - 1  # where each piece's end point goes
    pts = np.empty((int(at[-1]) + 1 if len(at) else 0, 2))
    pts[at] = b[idx]
    pts[at[first] - 1] = a[idx[first]]
    return [r for r in np.split(pts, (at[first] - 1)[1:]) if len(r)]
