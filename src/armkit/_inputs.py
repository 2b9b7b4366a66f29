"""The one input validator of numbers, angles, arrays and choices, for every package.

Every check raises ``InputError`` (an ``ArmkitError`` and a ``ValueError``) that
names the argument, what is allowed and what was given, shown briefly: numbers
to 6 significant digits, arrays by their shape (and a short vector's values),
never a raw array or a 309-digit number. ``mm`` and ``brief`` show a point and
a number the same way in every package's messages.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ._errors import InputError
from ._terminal import fixed

F64 = NDArray[np.float64]


def is_number(value: Any) -> bool:
    """Whether ``value`` is a real number: an int, a float or a numpy one, not a bool."""
    return isinstance(value, (int, float, np.integer, np.floating)) and not isinstance(value, bool)


def has_bool(value: Any) -> bool:
    """Whether ``value`` is or holds True or False (a bool, a bool array, or a tuple or
    list with one inside): numpy would read them as 1 and 0, armkit refuses them."""
    if isinstance(value, (bool, np.bool_)):
        return True
    if isinstance(value, np.ndarray):
        return bool(value.dtype == np.bool_)
    if isinstance(value, (tuple, list)):
        return any(has_bool(v) for v in value)
    return False


def shown(value: Any) -> str:
    """``value`` as a short string for a message."""
    if isinstance(value, np.ndarray):
        some = f": {shown(value.tolist())}" if 0 < value.size <= 6 and value.ndim == 1 else ""
        return f"an array of shape {value.shape}{some}"
    if isinstance(value, (bool, np.bool_)):
        return repr(bool(value))
    if isinstance(value, (int, float, np.integer, np.floating)):
        return f"{float(value):.6g}"
    if isinstance(value, (tuple, list)) and len(value) <= 6 and value != [] and value != ():
        inner = ", ".join(shown(v) for v in value)
        return f"({inner})" if isinstance(value, tuple) else f"[{inner}]"
    if value is None:
        return "None"
    if isinstance(value, str):
        return repr(value[:20])
    name = type(value).__name__
    return f"{'an' if name[:1].lower() in 'aeiou' else 'a'} {name}"


def array(
    value: ArrayLike, name: str, shapes: tuple[tuple[int | None, ...], ...], unit: str
) -> F64:
    """``value`` as finite float64 of one of ``shapes`` (None: any length)."""
    try:
        a = np.asarray(value, dtype=np.float64)
    except (TypeError, ValueError):
        raise InputError(f"{name} must be numbers [{unit}], got {shown(value)}") from None
    if has_bool(value):
        raise InputError(f"{name} must be numbers [{unit}], not True or False, got {shown(value)}")
    fits = any(
        a.ndim == len(s) and all(w is None or w == n for w, n in zip(s, a.shape, strict=True))
        for s in shapes
    )
    if not fits:
        want = " or ".join(
            "("
            + ", ".join("N" if w is None else str(w) for w in s)
            + (",)" if len(s) == 1 else ")")
            for s in shapes
        )
        raise InputError(f"{name} must have shape {want} [{unit}], got shape {a.shape}")
    if not np.all(np.isfinite(a)):
        raise InputError(f"{name} must be finite [{unit}], got NaN or infinity")
    return a


def point(value: Any, name: str = "position") -> tuple[float, float, float]:
    """Three finite floats (x, y, z) [m]; fast for a tuple or list of floats."""
    if isinstance(value, (tuple, list)) and len(value) == 3:
        x, y, z = value
        floats = type(x) is float and type(y) is float and type(z) is float
        if floats and x - x == 0.0 and y - y == 0.0 and z - z == 0.0:  # finite
            return x, y, z
    elif isinstance(value, np.ndarray) and value.shape == (3,) and value.dtype == np.float64:
        x, y, z = value.tolist()
        if x - x == 0.0 and y - y == 0.0 and z - z == 0.0:
            return x, y, z
    numbers = isinstance(value, np.ndarray) or (
        isinstance(value, (tuple, list)) and all(is_number(v) for v in value)
    )
    if not numbers or np.shape(value) != (3,):
        raise InputError(f"{name} must be three numbers (x, y, z) [m], got {shown(value)}")
    a = array(value, name, ((3,),), "m")
    return float(a[0]), float(a[1]), float(a[2])


def angle(value: Any, name: str) -> float | None:
    """A finite angle [rad] or None."""
    if value is None or (type(value) is float and value - value == 0.0):
        return value  # type: ignore[no-any-return]
    if not is_number(value):
        raise InputError(f"{name} must be a number [rad] or None, got {shown(value)}")
    v = float(value)
    if not math.isfinite(v):
        raise InputError(f"{name} must be finite [rad], got {shown(v)}")
    return v


def joints(value: ArrayLike, dof: int, name: str = "q", batch: bool = True) -> F64:
    """Joint angles [rad], shape (dof,) or, with ``batch``, (N, dof)."""
    shapes: tuple[tuple[int | None, ...], ...] = ((dof,), (None, dof)) if batch else ((dof,),)
    return array(value, name, shapes, "rad")


def rotation(value: ArrayLike, name: str, n: int | None = None) -> F64:
    """Rotation matrices, shape (3, 3) or (n, 3, 3), orthonormal with determinant +1."""
    R = array(value, name, ((3, 3),) if n is None else ((n, 3, 3),), "rotation matrix")
    if R.ndim == 2:
        ok = _is_rotation(R.ravel().tolist())
    else:
        RRt = np.einsum("...ij,...kj->...ik", R, R)
        ok = np.allclose(RRt, np.eye(3), atol=1e-6) and not np.any(np.linalg.det(R) < 0)
    if not ok:
        raise InputError(f"{name} must be a rotation matrix (orthonormal, determinant +1)")
    return R


def _is_rotation(r: list[float]) -> bool:
    """One finite 3x3 matrix (row-major) as ``rotation`` checks N at once, in floats:
    R R^T within ``np.allclose``'s default of the identity (atol 1e-6, rtol 1e-5) and
    determinant >= 0."""
    a, b, c, d, e, f, g, h, i = r
    for k, (x, y, z) in enumerate(((a, b, c), (d, e, f), (g, h, i))):
        for m, (u, v, w) in enumerate(((a, b, c), (d, e, f), (g, h, i))):
            if not abs(x * u + y * v + z * w - (k == m)) <= 1e-6 + 1e-5 * (k == m):
                return False
    return a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g) >= 0.0


def tolerance(value: Any, name: str) -> float:
    """A finite number > 0."""
    if not is_number(value):
        raise InputError(f"{name} must be a number > 0, got {shown(value)}")
    v = float(value)
    if not (math.isfinite(v) and v > 0.0):
        raise InputError(f"{name} must be a finite number > 0, got {shown(v)}")
    return v


def choice(value: Any, name: str, allowed: tuple[str, ...]) -> str:
    """One of ``allowed``."""
    if not isinstance(value, str) or value not in allowed:
        raise InputError(f"{name} must be one of {', '.join(allowed)}, got {shown(value)}")
    return value


def mm(p: Any) -> str:
    """A point [m] for a message in millimetres: ``(x, y, z) mm`` to 0.1 mm, 3 significant
    digits when huge, in metres when too far for millimetres in a float."""
    if all(math.isfinite(v * 1000.0) for v in p):
        return "(" + ", ".join(brief(float(v) * 1000.0) for v in p) + ") mm"
    return "(" + ", ".join(f"{float(v):.3g}" for v in p) + ") m"


def deg_text(angle: float) -> str:
    """An angle [rad] for a message: ``12.5 deg`` to 0.1 deg (never -0.0)."""
    return f"{round(math.degrees(angle), 1) + 0.0:.1f} deg"


def size_text(size: Any) -> str:
    """Sizes [m] for a message: ``40.0 x 30.0 x 20.0 mm``."""
    return " x ".join(f"{float(v) * 1000:.1f}" for v in size) + " mm"


def brief(v: float) -> str:
    """A number for a message: one decimal (``fixed``: no -0.0), or 3 significant digits
    when huge."""
    return fixed(v, 1) if abs(v) < 1e6 else f"{v:.3g}"
