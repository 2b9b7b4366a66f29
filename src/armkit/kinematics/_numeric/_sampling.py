"""Seeded joint vectors inside the limits: where restarts begin."""

from __future__ import annotations

import random

from .._chain import Chain


class JointSampler:
    """Uniform joint vectors inside a model's limits, reproducible from a seed.

    Args:
        chain: the arm's compiled chain.
        seed: the random seed; the same seed gives the same sequence.
    """

    def __init__(self, chain: Chain, seed: int) -> None:
        self._random = random.Random(seed)
        self._bounds = list(zip(chain.lower, chain.upper, strict=True))

    def sample(self) -> list[float]:
        """One joint vector [rad], dof floats, each inside its joint's limits."""
        uniform = self._random.uniform
        return [uniform(lo, hi) for lo, hi in self._bounds]


def clamp(q: list[float], lower: tuple[float, ...], upper: tuple[float, ...]) -> list[float]:
    """q [rad] with every joint clamped into [lower, upper], as Python floats."""
    out = []
    for v, a, b in zip(q, lower, upper, strict=True):
        t = float(v)
        out.append(a if t < a else (b if t > b else t))
    return out
