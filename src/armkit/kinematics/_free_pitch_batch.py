"""Position-only closed form for N targets on a 3-joint planar chain, vectorised.

The same search as the single-target one (``_analytic._free_pitch``): the
seed's pitch first, then pitches outwards in 3 deg steps both ways, then a
bisection towards the seed's pitch to 1e-4 rad; here each round solves every
target still pending at once. Targets the coarse scan misses go to the
single-target search, which also tries 0.1 deg steps.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
from numpy.typing import NDArray

from .._errors import UnreachableError
from ..model import ArmModel
from . import _analytic
from ._family import PlanarFamily
from ._fk import fk
from ._pose import pitch_of

F64 = NDArray[np.float64]
Bool = NDArray[np.bool_]
Solve = Callable[[F64, F64, F64], tuple[F64, Bool, NDArray[np.str_]]]
STEP = np.radians(3.0)


def free_pitch_batch(
    model: ArmModel, fam: PlanarFamily, P: F64, seed: F64, solve: Solve
) -> tuple[F64, Bool, NDArray[np.str_]]:
    """Best solution per target [rad] (N, dof), ok (N,), reason (N,).

    Args:
        P: targets [m], (N, 3).  seed: [rad], (N, dof).
        solve: the batch closed form for given pitches: (P, pitch, seed) -> (q, ok, reason).
    """
    preferred = np.asarray(pitch_of(fk(model, seed)), dtype=np.float64).reshape(len(P))
    q, ok, reason = solve(P, preferred, seed)
    hit, miss, found = _scan(P, seed, preferred, ~ok, solve)
    idx = np.flatnonzero(found)
    if idx.size:
        pitch = _bisect(P[idx], seed[idx], hit[idx], miss[idx], solve)
        q[idx], ok[idx], reason[idx] = solve(P[idx], pitch, seed[idx])
    for i in np.flatnonzero(~ok & ~found):
        _single(model, fam, P, seed, int(i), (q, ok, reason))
    return q, ok, reason


def _scan(P: F64, seed: F64, preferred: F64, pending: Bool, solve: Solve) -> tuple[F64, F64, Bool]:
    """Coarse scan: per target the first fitting pitch and the one before it."""
    pending = pending.copy()
    hit, miss = preferred.copy(), preferred.copy()
    found = np.zeros(len(P), dtype=bool)
    for k in range(1, 61):
        for sign in (1.0, -1.0):
            idx = np.flatnonzero(pending)
            if idx.size == 0:
                return hit, miss, found
            trial = preferred[idx] + sign * k * STEP
            _, okk, _ = solve(P[idx], trial, seed[idx])
            got = idx[okk]
            hit[got], miss[got] = trial[okk], preferred[got] + sign * (k - 1) * STEP
            found[got], pending[got] = True, False
    return hit, miss, found


def _bisect(P: F64, seed: F64, hit: F64, miss: F64, solve: Solve) -> F64:
    """Move each fitting pitch towards its miss until they are 1e-4 rad apart."""
    while np.max(np.abs(hit - miss)) > 1e-4:
        mid = 0.5 * (hit + miss)
        _, okm, _ = solve(P, mid, seed)
        hit, miss = np.where(okm, mid, hit), np.where(okm, miss, mid)
    return hit


def _single(
    model: ArmModel,
    fam: PlanarFamily,
    P: F64,
    seed: F64,
    i: int,
    out: tuple[F64, Bool, NDArray[np.str_]],
) -> None:
    """The single-target search for target i, written into ``out``."""
    q, ok, reason = out
    try:
        sols = _analytic.solve(model, fam, tuple(P[i].tolist()), None, tuple(seed[i].tolist()))
    except UnreachableError as exc:
        reason[i] = exc.reason
        return
    q[i], ok[i], reason[i] = sols[0], True, ""
