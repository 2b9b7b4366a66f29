"""Seeded joint vectors inside the limits: where restarts begin."""

from __future__ import annotations

import random

from ...model import ArmModel


class JointSampler:
    """Uniform joint vectors inside a model's limits, reproducible from a seed.

    Args:
        model: the arm.
        seed: the random seed; the same seed gives the same sequence.
    """

    def __init__(self, model: ArmModel, seed: int) -> None:
        self._random = random.Random(seed)
        self._bounds = [(j.lower, j.upper) for j in model.joints]

    def sample(self) -> list[float]:
        """One joint vector [rad], dof floats, each inside its joint's limits."""
        uniform = self._random.uniform
        return [uniform(lo, hi) for lo, hi in self._bounds]


def clamp_to_limits(model: ArmModel, q: list[float]) -> list[float]:
    """q [rad] with every joint clamped into its limits."""
    return clamp(q, [j.lower for j in model.joints], [j.upper for j in model.joints])


def clamp(q: list[float], lower: list[float], upper: list[float]) -> list[float]:
    """q [rad] with every joint clamped into [lower, upper], as Python floats."""
    out = []
    for v, a, b in zip(q, lower, upper, strict=True):
        t = float(v)
        out.append(a if t < a else (b if t > b else t))
    return out
