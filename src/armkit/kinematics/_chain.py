"""The DH chain as flat arrays, prepared once per model for fast evaluation."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ..model import ArmModel


@dataclass(frozen=True, eq=False)
class Chain:
    """Per-joint DH constants of one model, shape (dof,) each [m, rad]."""

    modified: bool
    a: NDArray[np.float64]
    d: NDArray[np.float64]
    ca: NDArray[np.float64]
    sa: NDArray[np.float64]
    offset: NDArray[np.float64]
    sign: NDArray[np.float64]
    T_tool: NDArray[np.float64]
    # Python-float copies for the scalar paths.
    rows: tuple[tuple[float, float, float, float, float, float], ...]


def chain_of(model: ArmModel) -> Chain:
    """The model's ``Chain``, built once and cached on the model."""
    chain = model._cache.get("chain")
    if chain is None:
        chain = _build(model)
        model._cache["chain"] = chain
    return chain  # type: ignore[no-any-return]


def _build(model: ArmModel) -> Chain:
    a = np.array([r.a for r in model.dh])
    d = np.array([r.d for r in model.dh])
    alpha = np.array([r.alpha for r in model.dh])
    ca, sa = np.cos(alpha), np.sin(alpha)
    ca[np.abs(ca) < 1e-15] = 0.0
    sa[np.abs(sa) < 1e-15] = 0.0
    offset = np.array([r.theta_offset for r in model.dh])
    sign = np.array([r.sign for r in model.dh])
    rows = tuple(
        (float(a[i]), float(d[i]), float(ca[i]), float(sa[i]), float(offset[i]), float(sign[i]))
        for i in range(model.dof)
    )
    return Chain(
        modified=model.convention == "modified",
        a=a,
        d=d,
        ca=ca,
        sa=sa,
        offset=offset,
        sign=sign,
        T_tool=model.T_flange_tool,
        rows=rows,
    )
