"""Math written once over lanes: every quantity a float (one target) or a numpy array of
shape (k,) (k targets). Arithmetic is the same for both; the few functions that are not
come from ``FLOATS`` (``math``, conditional expressions) or ``LANES`` (numpy)."""

from __future__ import annotations

import math
from typing import Any, NamedTuple

import numpy as np


class Ops(NamedTuple):
    """The functions that differ between floats and lanes."""

    sqrt: Any
    hypot: Any
    atan2: Any
    maximum: Any
    floor: Any
    cos: Any
    sin: Any
    where: Any  # where(condition, a, b): a where the condition holds, else b


def _where(condition: bool, a: float, b: float) -> float:
    return a if condition else b


FLOATS = Ops(math.sqrt, math.hypot, math.atan2, max, math.floor, math.cos, math.sin, _where)
LANES = Ops(np.sqrt, np.hypot, np.arctan2, np.maximum, np.floor, np.cos, np.sin, np.where)
