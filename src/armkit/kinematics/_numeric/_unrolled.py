"""``chain_state`` written out for one chain: no loop, the DH constants in place.

The plain-float loop in ``_scalar_chain`` is the reference. For the solvers'
inner loop the same statements are emitted once per model as Python source,
one block per DH row, with every zero term dropped and every constant a
literal, and compiled: the same floating-point operations in the same order
(so the results are bit-identical, which the tests check), at about half the
cost, since the interpreter no longer unpacks rows or tests for zeros.
``source_of`` returns the code, to read it.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

Row = tuple[float, float, float, float, float, float]
ToolColumn = tuple[int, float] | None


def compile_chain(
    modified: bool,
    rows: tuple[Row, ...],
    tool_R: tuple[float, ...],
    tool_axes: tuple[ToolColumn, ToolColumn, ToolColumn],
    tool_offsets: tuple[tuple[int, float], ...],
    state_type: type,
) -> Callable[[list[float]], Any]:
    """The function q [rad] -> ``state_type(p, R, axes, origins)`` for this chain."""
    source = source_of(modified, rows, tool_R, tool_axes, tool_offsets)
    namespace: dict[str, Any] = {"cos": math.cos, "sin": math.sin, "ChainState": state_type}
    exec(compile(source, "<armkit unrolled chain>", "exec"), namespace)
    fn: Callable[[list[float]], Any] = namespace["chain_state"]
    return fn


def source_of(
    modified: bool,
    rows: tuple[Row, ...],
    tool_R: tuple[float, ...],
    tool_axes: tuple[ToolColumn, ToolColumn, ToolColumn],
    tool_offsets: tuple[tuple[int, float], ...],
) -> str:
    """Python source of ``chain_state(q)`` for one chain (see the module docstring)."""
    names = ", ".join(f"q{i}" for i in range(len(rows)))
    lines = [
        "def chain_state(q):",
        f"    {names}{',' if len(rows) == 1 else ''} = q",
        "    ax, ay, az, bx, by, bz, cx, cy, cz = 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0",
        "    px = py = pz = 0.0",
    ]
    block = _modified_row if modified else _standard_row
    for i, row in enumerate(rows):
        lines += ["    " + s for s in block(i, row)]
    lines += ["    " + s for s in _tool(tool_R, tool_axes, tool_offsets)]
    axes = ", ".join(f"z{i}" for i in range(len(rows)))
    origins = ", ".join(f"o{i}" for i in range(len(rows)))
    lines.append(f"    return ChainState((tx, ty, tz), (r0, r1, r2), [{axes}], [{origins}])")
    return "\n".join(lines) + "\n"


def _modified_row(i: int, row: Row) -> list[str]:
    """Rx(alpha) Tx(a) Rz(theta) Tz(d), as ``_modified_frames`` does it."""
    a, d, ca, sa, off, sign = row
    out = _translate(a, "a") + _rotate_x(ca, sa) + _rotate_z(i, off, sign) + _translate(d, "c")
    return [*out, *_joint(i, sign)]


def _standard_row(i: int, row: Row) -> list[str]:
    """Rz(theta) Tz(d) Tx(a) Rx(alpha), as ``_standard_frames`` does it."""
    a, d, ca, sa, off, sign = row
    out = _joint(i, sign) + _rotate_z(i, off, sign) + _translate(d, "c") + _translate(a, "a")
    return out + _rotate_x(ca, sa)


def _joint(i: int, sign: float) -> list[str]:
    """Joint i's signed axis z{i} (the current z column) and a point on it, o{i}."""
    axis = "(cx, cy, cz)" if sign > 0.0 else "(-cx, -cy, -cz)"
    return [f"z{i} = {axis}", f"o{i} = (px, py, pz)"]


def _translate(length: float, col: str) -> list[str]:
    """p += length * (column col), skipped for a zero length."""
    if not length:
        return []
    k = repr(length)
    return [f"px += {k} * {col}x", f"py += {k} * {col}y", f"pz += {k} * {col}z"]


def _rotate_x(ca: float, sa: float) -> list[str]:
    """Columns b, c after Rx(alpha), as ``_scalar_chain._rotate_x`` (nothing for alpha = 0)."""
    if ca == 1.0:
        return []
    c, s = repr(ca), repr(sa)
    if ca == 0.0:
        n = repr(-sa)
        return [
            f"bx, by, bz, cx, cy, cz = {s} * cx, {s} * cy, {s} * cz, {n} * bx, {n} * by, {n} * bz"
        ]
    return [
        f"bx, by, bz, cx, cy, cz = ({c} * bx + {s} * cx, {c} * by + {s} * cy, {c} * bz + {s} * cz, "
        f"{c} * cx - {s} * bx, {c} * cy - {s} * by, {c} * cz - {s} * bz)"
    ]


def _rotate_z(i: int, off: float, sign: float) -> list[str]:
    """Columns a, b after Rz(theta), theta = sign q_i + offset."""
    theta = f"{'' if sign > 0.0 else '-'}q{i}" if abs(sign) == 1.0 else f"{sign!r} * q{i}"
    return [
        f"th = {theta} + {off!r}" if off else f"th = {theta}",
        "c, s = cos(th), sin(th)",
        "t0, t1, t2 = c * ax + s * bx, c * ay + s * by, c * az + s * bz",
        "bx, by, bz = c * bx - s * ax, c * by - s * ay, c * bz - s * az",
        "ax, ay, az = t0, t1, t2",
    ]


def _tool(
    R: tuple[float, ...],
    axes: tuple[ToolColumn, ToolColumn, ToolColumn],
    offsets: tuple[tuple[int, float], ...],
) -> list[str]:
    """The tool point (tx, ty, tz) and rotation columns r0..r2, as ``_scalar_chain._tool``."""
    cols = "abc"
    out = ["tx, ty, tz = px, py, pz"]
    for k, length in offsets:
        f, v = cols[k], repr(length)
        out.append(f"tx, ty, tz = (tx + {v} * {f}x, ty + {v} * {f}y, tz + {v} * {f}z)")
    for j, axis in enumerate(axes):
        if axis is not None and all(a is not None for a in axes):
            f = cols[axis[0]]
            sign = "" if axis[1] > 0.0 else "-"
            out.append(
                f"r{j} = ({sign}{f}x, {sign}{f}y, {sign}{f}z)"
                if sign
                else f"r{j} = ({f}x, {f}y, {f}z)"
            )
        else:
            t0, t1, t2 = (repr(R[3 * m + j]) for m in range(3))
            out.append(
                f"r{j} = (ax * {t0} + bx * {t1} + cx * {t2}, ay * {t0} + by * {t1} + cy * {t2}, "
                f"az * {t0} + bz * {t1} + cz * {t2})"
            )
    return out
