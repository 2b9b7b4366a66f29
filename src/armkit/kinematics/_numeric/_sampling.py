"""Seeded joint vectors inside the limits: where restarts begin."""

from __future__ import annotations

import random
from collections.abc import Callable

from .._chain import Chain


def joint_sampler(chain: Chain, seed: int) -> Callable[[], list[float]]:
    """Uniform joint vectors inside the chain's limits, reproducible from ``seed`` (the
    same seed, the same sequence): each call gives one, dof floats [rad]."""
    uniform, bounds = random.Random(seed).uniform, list(zip(chain.lower, chain.upper, strict=True))
    return lambda: [uniform(lo, hi) for lo, hi in bounds]


def clamp(q: list[float], lower: tuple[float, ...], upper: tuple[float, ...]) -> list[float]:
    """q [rad] with every joint clamped into [lower, upper], as Python floats."""
    out = []
    for v, a, b in zip(q, lower, upper, strict=True):
        t = float(v)
        out.append(a if t < a else (b if t > b else t))
    return out
