"""The damped least-squares step (the baselines' and the LM reference's): the scalar fast
variants against the definition, dq = argmin |J dq - e|^2 + lam |dq|^2, i.e.
(J^T J + lam I) dq = J^T e."""

from __future__ import annotations

import numpy as np
import pytest

from armkit.kinematics._numeric._dls import dls_step

SIZES = [(m, n) for m in (3, 4, 6) for n in range(2, 7)]


def _case(m: int, n: int, seed: int) -> tuple[list[tuple[float, ...]], list[float], float]:
    rng = np.random.default_rng(seed)
    cols = [tuple(rng.uniform(-1.0, 1.0, m).tolist()) for _ in range(n)]
    return cols, rng.uniform(-1.0, 1.0, m).tolist(), float(10.0 ** rng.uniform(-6.0, 0.0))


def _definition(cols: list[tuple[float, ...]], e: list[float], lam: float) -> np.ndarray:
    J = np.array(cols).T  # (m, n)
    return np.linalg.solve(J.T @ J + lam * np.eye(J.shape[1]), J.T @ np.array(e))


@pytest.mark.parametrize(("m", "n"), SIZES)
def test_fast_variants_equal_the_definition(m: int, n: int) -> None:
    for seed in range(20):
        cols, e, lam = _case(m, n, seed)
        ref = _definition(cols, e, lam)
        np.testing.assert_allclose(dls_step(cols, e, lam, None), ref, rtol=1e-7, atol=1e-9)
