"""The compiled LM kernel (``_lmc.c``); see ``_lm`` for its use. Buffers are C-contiguous
float64 (bytes for the packed chain and a single target)."""

from collections.abc import Sequence

import numpy as np
from numpy.typing import NDArray

_Buf = bytes | NDArray[np.float64]

def solve_one(
    chain: _Buf, mode: int, target: _Buf, seed: Sequence[float], tol_pos: float,
    tol_ang: float, rng_seed: int, /,
) -> tuple[tuple[float, ...], int, int, int, float, float, float]: ...  # fmt: skip
def solve_many(
    chain: _Buf, mode: int, targets: _Buf, seeds: _Buf, q_out: _Buf, outcomes_out: _Buf,
    tol_pos: float, tol_ang: float, rng_seed: int, /,
) -> None: ...  # fmt: skip
