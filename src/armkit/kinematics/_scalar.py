"""Tool pose and Jacobian for ONE joint vector in plain floats: the scalar fast path.

For 2-6 joints plain floats beat numpy's per-call overhead tenfold. The steps of
``_steps`` are written out once per chain as Python source (every zero term
dropped, every constant a literal) and compiled; tests pin it to ``_forward``.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

from ._steps import Fixed, Step, Terms

Vec3 = tuple[float, float, float]
_COLS = ("a", "b", "c")


class ChainState:
    """Tool pose and Jacobian at one q; the linear part is computed on first use.

    Attributes:
        p: tool point [m].
        R: tool rotation columns (x = approach, y, z), each a unit Vec3.
        jw: per joint, the angular velocity per unit angle (signed joint axis).
        origins: per joint, a point on its axis [m].
    """

    __slots__ = ("R", "_jv", "jw", "origins", "p")

    def __init__(self, p: Vec3, R: tuple[Vec3, Vec3, Vec3], jw: list[Vec3], origins: list[Vec3]):
        self.p, self.R, self.jw, self.origins = p, R, jw, origins
        self._jv: list[Vec3] | None = None

    @property
    def jv(self) -> list[Vec3]:
        """Per joint, axis x (tool point - point on the axis) [m/rad]."""
        if self._jv is None:
            px, py, pz = self.p
            jv = []
            for (zx, zy, zz), (ox, oy, oz) in zip(self.jw, self.origins, strict=True):
                dx, dy, dz = px - ox, py - oy, pz - oz
                jv.append((zy * dz - zz * dy, zz * dx - zx * dz, zx * dy - zy * dx))
            self._jv = jv
        return self._jv


State = Callable[[list[float]], ChainState]


def compile_state(steps: tuple[Step, ...], tool: Fixed) -> State:
    """The function q [rad] (dof floats) -> ``ChainState`` for this chain."""
    namespace: dict[str, Any] = {"cos": math.cos, "sin": math.sin, "ChainState": ChainState}
    exec(compile(source_of(steps, tool), "<armkit chain>", "exec"), namespace)
    fn: State = namespace["chain_state"]
    return fn


def source_of(steps: tuple[Step, ...], tool: Fixed) -> str:
    """Python source of ``chain_state(q)`` for one chain (see the module docstring)."""
    n = len(steps)
    lines = [
        "def chain_state(q):",
        f"    {', '.join(f'q{i}' for i in range(n))}{',' if n == 1 else ''} = q",
        "    ax, ay, az, bx, by, bz, cx, cy, cz = 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0",
        "    px = py = pz = 0.0",
    ]
    for i, step in enumerate(steps):
        lines += ["    " + s for s in _fixed(step.before) + _joint(i, step)]
    lines += ["    " + s for s in _fixed(tool)]
    axes, origins = ", ".join(f"z{i}" for i in range(n)), ", ".join(f"o{i}" for i in range(n))
    lines.append(
        "    return ChainState((px, py, pz), ((ax, ay, az), (bx, by, bz), (cx, cy, cz)), "
        f"[{axes}], [{origins}])"
    )
    return "\n".join(lines) + "\n"


def _sum(terms: Terms, axis: str) -> str:
    """sum_k coefficient_k * column_k's ``axis`` component, with unit coefficients bare."""
    out = ""
    for k, v in terms:
        name = f"{_COLS[k]}{axis}"
        term = name if abs(v) == 1.0 else f"{abs(v)!r} * {name}"
        out += ("-" if v < 0 else "") + term if not out else (" - " if v < 0 else " + ") + term
    return out


def _fixed(F: Fixed) -> list[str]:
    """p += the shift; then the rotation columns that change, all at once."""
    out = [f"p{x} += {_sum(F.shift, x)}" for x in "xyz"] if F.shift else []
    names, values = [], []
    for j, terms in enumerate(F.columns):
        if terms is not None:
            names += [f"{_COLS[j]}{x}" for x in "xyz"]
            values += [_sum(terms, x) for x in "xyz"]
    if names:
        out.append(f"{', '.join(names)} = {', '.join(values)}")
    return out


def _joint(i: int, step: Step) -> list[str]:
    """Joint i's signed axis z{i}, a point on it o{i}, then the turn about z."""
    axis = "(cx, cy, cz)" if step.sign > 0.0 else "(-cx, -cy, -cz)"
    theta = f"{'' if step.sign > 0.0 else '-'}q{i}"
    return [
        f"z{i} = {axis}",
        f"o{i} = (px, py, pz)",
        f"th = {theta} + {step.offset!r}" if step.offset else f"th = {theta}",
        "c, s = cos(th), sin(th)",
        "ax, ay, az, bx, by, bz = (c * ax + s * bx, c * ay + s * by, c * az + s * bz, "
        "c * bx - s * ax, c * by - s * ay, c * bz - s * az)",
    ]
