"""Tool pose and geometric Jacobian for ONE joint vector, in plain Python floats.

For 2-6 joints, plain float arithmetic beats numpy's per-call overhead by an
order of magnitude, which is what a single-target iterative solver needs.
Same conventions as ``armkit.kinematics.fk`` / ``jacobian`` (checked by tests).
``chain_state`` runs code unrolled for the model (``_unrolled``);
``chain_state_loop`` is the same computation as a loop over the DH rows.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

from ...model import ArmModel
from .._chain import chain_of
from ._unrolled import compile_chain

Vec3 = tuple[float, float, float]
Row = tuple[float, float, float, float, float, float]


ToolColumn = tuple[int, float] | None  # (flange column k, sign) when a tool axis is +-one of them


@dataclass(frozen=True, slots=True)
class ScalarChain:
    """The DH rows and the tool as Python floats.

    Attributes:
        modified: True for modified (Craig) DH.
        rows: per joint (a [m], d [m], cos alpha, sin alpha, theta offset [rad], sign).
        tool_R: rotation of T_flange_tool, row-major, 9 floats.
        tool_p: translation of T_flange_tool [m].
        tool_axes: per tool axis, (k, sign) if it is sign times flange axis k
            (tools are usually mounted square: no arithmetic needed), else None.
        tool_offsets: the nonzero entries of tool_p as (flange axis k, length [m]).
        state: ``chain_state`` for this chain, unrolled (see ``_unrolled``).
    """

    modified: bool
    rows: tuple[Row, ...]
    tool_R: tuple[float, ...]
    tool_p: Vec3
    tool_axes: tuple[ToolColumn, ToolColumn, ToolColumn]
    tool_offsets: tuple[tuple[int, float], ...]
    state: Callable[[list[float]], ChainState]


class ChainState:
    """Tool pose and Jacobian at one q; the linear part is computed on first use.

    Attributes:
        p: tool point [m].
        R: tool rotation columns (x = approach, y, z), each a unit Vec3.
        jw: per joint, the angular velocity per unit angle (signed joint axis).
        origins: per joint, a point on its axis [m].
        jv: per joint, the tool point's linear velocity per unit angle [m/rad].
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


def scalar_chain(model: ArmModel) -> ScalarChain:
    """The model's ``ScalarChain``, built once and cached on the model."""
    sc = model._cache.get("scalar_chain")
    if sc is None:
        chain = chain_of(model)
        t = chain.T_tool
        R = tuple(float(t[i, j]) for i in range(3) for j in range(3))
        p = (float(t[0, 3]), float(t[1, 3]), float(t[2, 3]))
        axes = (_tool_axis(R, 0), _tool_axis(R, 1), _tool_axis(R, 2))
        offsets = tuple((k, v) for k, v in enumerate(p) if abs(v) > _EXACT)
        state = compile_chain(chain.modified, chain.rows, R, axes, offsets, ChainState)
        sc = ScalarChain(chain.modified, chain.rows, R, p, axes, offsets, state)
        model._cache["scalar_chain"] = sc
    return sc  # type: ignore[no-any-return]


_EXACT = 1e-15  # tool entries this small are rounding noise of a square mount


def _tool_axis(R: tuple[float, ...], j: int) -> ToolColumn:
    """(k, sign) when column j of R is sign times unit vector k (within _EXACT), else None."""
    col = [R[j], R[3 + j], R[6 + j]]
    big = [k for k, v in enumerate(col) if abs(v) > _EXACT]
    if len(big) == 1 and abs(abs(col[big[0]]) - 1.0) <= _EXACT:
        return big[0], math.copysign(1.0, col[big[0]])
    return None


def chain_state(sc: ScalarChain, q: list[float]) -> ChainState:
    """Tool pose and Jacobian for joint angles q [rad], length dof (unrolled code,
    equal to ``chain_state_loop``'s to the last bit)."""
    return sc.state(q)


def chain_state_loop(sc: ScalarChain, q: list[float]) -> ChainState:
    """``chain_state`` by a loop over the DH rows: the readable reference."""
    axes, origins, R, p = _frames(sc, q)
    return ChainState(p, R, axes, origins)


def _frames(
    sc: ScalarChain, q: list[float]
) -> tuple[list[Vec3], list[Vec3], tuple[Vec3, Vec3, Vec3], Vec3]:
    """Signed joint axes, points on them, tool rotation columns and tool point."""
    if sc.modified:
        axes, origins, a, b, c, p = _modified_frames(sc.rows, q)
    else:
        axes, origins, a, b, c, p = _standard_frames(sc.rows, q)
    return axes, origins, *_tool(sc, a, b, c, p)


Frames = tuple[list[Vec3], list[Vec3], Vec3, Vec3, Vec3, Vec3]


def _modified_frames(rows: tuple[Row, ...], q: list[float]) -> Frames:
    """Right-multiply by Rx(alpha) Tx(a) Rz(theta) Tz(d) per row; zero terms skipped."""
    a, b, c, p = _IDENTITY
    axes: list[Vec3] = []
    origins: list[Vec3] = []
    for (length, d, ca, sa, off, sign), qi in zip(rows, q, strict=True):
        p = _moved(p, length, a)
        b, c = _rotate_x(ca, sa, b, c)
        a, b = _rotate_z(sign * qi + off, a, b)
        p = _moved(p, d, c)
        axes.append(c if sign > 0.0 else (-c[0], -c[1], -c[2]))
        origins.append(p)
    return axes, origins, a, b, c, p


def _standard_frames(rows: tuple[Row, ...], q: list[float]) -> Frames:
    """Right-multiply by Rz(theta) Tz(d) Tx(a) Rx(alpha) per row; zero terms skipped."""
    a, b, c, p = _IDENTITY
    axes: list[Vec3] = []
    origins: list[Vec3] = []
    for (length, d, ca, sa, off, sign), qi in zip(rows, q, strict=True):
        axes.append(c if sign > 0.0 else (-c[0], -c[1], -c[2]))
        origins.append(p)
        a, b = _rotate_z(sign * qi + off, a, b)
        p = _moved(_moved(p, d, c), length, a)
        b, c = _rotate_x(ca, sa, b, c)
    return axes, origins, a, b, c, p


_IDENTITY: tuple[Vec3, Vec3, Vec3, Vec3] = (
    (1.0, 0.0, 0.0),
    (0.0, 1.0, 0.0),
    (0.0, 0.0, 1.0),
    (0.0, 0.0, 0.0),
)


def _moved(p: Vec3, length: float, axis: Vec3) -> Vec3:
    """p + length * axis [m] (p itself for a zero length)."""
    if not length:
        return p
    return (p[0] + length * axis[0], p[1] + length * axis[1], p[2] + length * axis[2])


def _rotate_z(theta: float, a: Vec3, b: Vec3) -> tuple[Vec3, Vec3]:
    """The x and y columns (a, b) after a rotation by theta [rad] about z."""
    c, s = math.cos(theta), math.sin(theta)
    return (
        (c * a[0] + s * b[0], c * a[1] + s * b[1], c * a[2] + s * b[2]),
        (c * b[0] - s * a[0], c * b[1] - s * a[1], c * b[2] - s * a[2]),
    )


def _rotate_x(ca: float, sa: float, b: Vec3, c: Vec3) -> tuple[Vec3, Vec3]:
    """The y and z columns (b, c) after a rotation by alpha about x (cos ca, sin sa)."""
    if ca == 1.0:
        return b, c
    if ca == 0.0:  # +-90 degrees, the common twist
        return (sa * c[0], sa * c[1], sa * c[2]), (-sa * b[0], -sa * b[1], -sa * b[2])
    return (
        (ca * b[0] + sa * c[0], ca * b[1] + sa * c[1], ca * b[2] + sa * c[2]),
        (ca * c[0] - sa * b[0], ca * c[1] - sa * b[1], ca * c[2] - sa * b[2]),
    )


def _tool(
    sc: ScalarChain, a: Vec3, b: Vec3, c: Vec3, p: Vec3
) -> tuple[tuple[Vec3, Vec3, Vec3], Vec3]:
    """Right-multiply the flange frame (columns a, b, c, origin p) by T_flange_tool."""
    flange = (a, b, c)
    tip = p
    for k, length in sc.tool_offsets:
        f = flange[k]
        tip = (tip[0] + length * f[0], tip[1] + length * f[1], tip[2] + length * f[2])
    ax, ay, az = sc.tool_axes
    if ax is not None and ay is not None and az is not None:
        return (_signed(flange, ax), _signed(flange, ay), _signed(flange, az)), tip
    return _rotate_columns(sc.tool_R, a, b, c), tip


def _signed(flange: tuple[Vec3, Vec3, Vec3], axis: tuple[int, float]) -> Vec3:
    f = flange[axis[0]]
    return f if axis[1] > 0.0 else (-f[0], -f[1], -f[2])


def _rotate_columns(t: tuple[float, ...], a: Vec3, b: Vec3, c: Vec3) -> tuple[Vec3, Vec3, Vec3]:
    """Columns of [a b c] @ t for a row-major 3 x 3 t."""
    t00, t01, t02, t10, t11, t12, t20, t21, t22 = t
    return (
        (a[0] * t00 + b[0] * t10 + c[0] * t20, a[1] * t00 + b[1] * t10 + c[1] * t20,
         a[2] * t00 + b[2] * t10 + c[2] * t20),
        (a[0] * t01 + b[0] * t11 + c[0] * t21, a[1] * t01 + b[1] * t11 + c[1] * t21,
         a[2] * t01 + b[2] * t11 + c[2] * t21),
        (a[0] * t02 + b[0] * t12 + c[0] * t22, a[1] * t02 + b[1] * t12 + c[1] * t22,
         a[2] * t02 + b[2] * t12 + c[2] * t22),
    )  # fmt: skip
