"""Checked command-line values: every number bounded and finite, the config folder
writable (output files: ``armkit._files.check_output_path``), all before anything is
planned or moved.

The ``type=`` functions here run inside argparse, so a bad value becomes the one
line ``armkit: error: argument --spacing: ...`` naming the argument, what is
allowed and what was typed, in the units the user typed.
"""

from __future__ import annotations

import argparse
import math
from collections.abc import Callable
from pathlib import Path

from .._errors import InputError
from .._files import folder_problem

COORD_MM = 100_000.0  # |x|, |y|, |z| of any target [mm]
ANGLE_DEG = 360.0  # |angle| of a joint, a pitch or a start angle [deg]
SWEEP_DEG = 3600.0  # |sweep| of an arc [deg]: ten turns
SIZE_MM = 10_000.0  # radius, width, depth, edge of a drawn shape [mm]
MAX_POINTS = 20_000  # waypoints in one drawing
MAX_DRAW_S = 600.0  # longest timed drawing [s]
IMAGE_SUFFIXES = tuple(
    f".{t}"
    for t in ("png", "pdf", "svg", "svgz", "jpg", "jpeg", "eps", "ps", "tif", "tiff", "webp")
)  # what matplotlib writes


def _fmt(value: float) -> str:
    """A bound as people write it: 100000, 0.1, 3600."""
    return f"{value:g}" if abs(value) < 1e6 else f"{value:.0f}"


def number(
    unit: str,
    low: float,
    high: float,
    *,
    low_open: bool = False,
    nonzero: bool = False,
) -> Callable[[str], float]:
    """An argparse type: a finite float in [low, high] (``(low, high]`` with ``low_open``)."""
    if low_open:
        span = f"> {_fmt(low)} and <= {_fmt(high)} {unit}".rstrip()
    else:
        span = f"{_fmt(low)}..{_fmt(high)} {unit}".rstrip()
    kind = f"a number of {unit}" if unit else "a number"

    def parse(text: str) -> float:
        try:
            value = float(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"must be {kind}, got {text!r}") from None
        ok = math.isfinite(value) and value <= high and (value > low if low_open else value >= low)
        if not ok or (nonzero and value == 0.0):
            extra = ", not 0" if nonzero else ""
            raise argparse.ArgumentTypeError(f"must be {span}{extra}, got {text}")
        return value

    parse.__name__ = kind
    return parse


def percent(low: float, high: float, *, low_open: bool = False) -> Callable[[str], float]:
    """An argparse type: a percentage in [low, high] (``(low, high]`` with ``low_open``),
    written ``50`` or ``50%`` as in a script (``speed 50%``) [%]."""
    parse = number("%", low, high, low_open=low_open)

    def percentage(text: str) -> float:
        return parse(text.strip().removesuffix("%"))

    percentage.__name__ = parse.__name__
    return percentage


def integer(what: str, low: int, high: int) -> Callable[[str], int]:
    """An argparse type: an integer in [low, high]."""

    def parse(text: str) -> int:
        try:
            value = int(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"must be a whole number, got {text!r}") from None
        if not low <= value <= high:
            span = f"{low}..{high} {what}".rstrip()
            raise argparse.ArgumentTypeError(f"must be {span}, got {text}")
        return value

    parse.__name__ = what or "whole number"
    return parse


coordinate = number("mm", -COORD_MM, COORD_MM)
angle = number("deg", -ANGLE_DEG, ANGLE_DEG)


def check_folder(folder: Path, what: str) -> None:
    """InputError unless files can be made in ``folder``, or in the folder above it
    that it would be created in (proven with a temporary file). Creates nothing else."""
    why = folder_problem(folder)
    if why is not None:
        raise InputError(
            f"{what} {folder} cannot be written ({why}); set ARMKIT_CONFIG_DIR to a writable directory"
        )
