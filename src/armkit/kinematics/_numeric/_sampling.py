"""Seeded joint vectors inside the limits: where restarts begin."""

from __future__ import annotations


def clamp(q: list[float], lower: tuple[float, ...], upper: tuple[float, ...]) -> list[float]:
    """q [rad] with every joint clamped into [lower, upper], as Python floats."""
    out = []
    for v, a, b in zip(q, lower, upper, strict=True):
        t = float(v)
        out.append(a if t < a else (b if t > b else t))
    return out
