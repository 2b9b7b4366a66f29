"""The chain's forward kinematics as generated Python: one source, run over floats or lanes.

The steps of ``_steps`` are written out once per chain as Python source (every
zero term dropped, every constant a literal) and compiled twice: with
``math``'s cos and sin for ONE joint vector in plain floats (for 2-6 joints
tenfold faster than numpy's per-call overhead), and with numpy's for N joint
vectors, each quantity a lane of shape (N,) (``_forward``'s batches). Tests pin
both to the dense product of the steps' 4x4 transforms (``fk_frames``).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any, Generic, TypeVar

import numpy as np
from numpy.typing import NDArray

from ._steps import Fixed, Step, Terms

N = TypeVar("N", float, NDArray[np.float64])  # a float, or a lane: one value per pose (N,)
Vec3 = tuple[float, float, float]
_COLS = ("a", "b", "c")


class ChainState(Generic[N]):
    """Tool pose and Jacobian at one q (floats) or at N (lanes); the linear part on first use.

    Attributes:
        p: tool point [m].
        R: tool rotation columns (x = approach, y, z), each a unit vector.
        jw: per joint, the angular velocity per unit angle (signed joint axis).
        origins: per joint, a point on its axis [m].
    A lane that does not depend on q (a zero, say) may stay a float.
    """

    __slots__ = ("R", "_jv", "jw", "origins", "p")
    p: tuple[N, N, N]
    R: tuple[tuple[N, N, N], tuple[N, N, N], tuple[N, N, N]]
    jw: list[tuple[N, N, N]]
    origins: list[tuple[N, N, N]]

    def __init__(
        self, p: tuple[N, N, N], R: tuple[tuple[N, N, N], tuple[N, N, N], tuple[N, N, N]],
        jw: list[tuple[N, N, N]], origins: list[tuple[N, N, N]],
    ) -> None:  # fmt: skip
        self.p, self.R, self.jw, self.origins = p, R, jw, origins
        self._jv: list[tuple[N, N, N]] | None = None

    @property
    def jv(self) -> list[tuple[N, N, N]]:
        """Per joint, axis x (tool point - point on the axis) [m/rad]."""
        if self._jv is None:
            px, py, pz = self.p
            jv = []
            for (zx, zy, zz), (ox, oy, oz) in zip(self.jw, self.origins, strict=True):
                dx, dy, dz = px - ox, py - oy, pz - oz
                jv.append((zy * dz - zz * dy, zz * dx - zx * dz, zx * dy - zy * dx))
            self._jv = jv
        return self._jv


State = Callable[[list[float]], ChainState[float]]
Lanes = Callable[[list[NDArray[np.float64]]], ChainState[NDArray[np.float64]]]
Pose = Callable[[list[float]], tuple[float, ...]]


def compile_state(steps: tuple[Step, ...], tool: Fixed) -> tuple[State, Lanes, Pose]:
    """The chain's functions q (dof floats) [rad] -> ``ChainState``, and q (dof lanes (N,))
    [rad] -> ``ChainState`` of lanes: one source (``source_of``) compiled twice; and the
    same source without the axes, q -> the tool pose's 16 entries row-major (``fk``'s)."""
    out: list[Any] = []
    for xm, pose in ((math, False), (np, False), (math, True)):
        code = compile(source_of(steps, tool, pose), "<armkit chain>", "exec")
        namespace: dict[str, Any] = {"cos": xm.cos, "sin": xm.sin, "ChainState": ChainState}
        exec(code, namespace)
        out.append(namespace["chain_state"])
    return out[0], out[1], out[2]


def source_of(steps: tuple[Step, ...], tool: Fixed, pose: bool = False) -> str:
    """Python source of ``chain_state(q)`` for one chain (see the module docstring); with
    ``pose``, of the tool pose alone as 16 floats, row-major."""
    n = len(steps)
    lines = [
        "def chain_state(q):",
        f"    {', '.join(f'q{i}' for i in range(n))}{',' if n == 1 else ''} = q",
        "    ax, ay, az, bx, by, bz, cx, cy, cz = 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0",
        "    px = py = pz = 0.0",
    ]
    for i, step in enumerate(steps):
        lines += ["    " + s for s in _fixed(step.before) + _joint(i, step)[2 * pose :]]
    lines += ["    " + s for s in _fixed(tool)]
    if pose:
        row = "a{0}, b{0}, c{0}, p{0}"
        rows = ", ".join(row.format(x) for x in "xyz")
        return "\n".join([*lines, f"    return ({rows}, 0.0, 0.0, 0.0, 1.0)"]) + "\n"
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
    out = [f"p{x} = p{x} + {_sum(F.shift, x)}" for x in "xyz"] if F.shift else []
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
