"""The damped least-squares step: the scalar fast variants and the batch form (the one
Cholesky factorisation, on lanes) against the definition, dq = argmin |J dq - e|^2 +
lam |dq|^2, i.e. (J^T J + lam I) dq = J^T e."""

from __future__ import annotations

import numpy as np
import pytest

from armkit.kinematics._numeric._dls import damped_steps, dls_step

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


@pytest.mark.parametrize(("m", "n"), SIZES)
def test_batch_steps_equal_the_definition_frozen_joints_included(m: int, n: int) -> None:
    cases = [_case(m, n, seed) for seed in range(12)]
    J = np.array([np.array(cols).T for cols, _, _ in cases])  # (k, m, n)
    e = np.array([c[1] for c in cases])
    lam = np.array([c[2] for c in cases])
    free = np.random.default_rng(1).uniform(size=(len(cases), n)) > 0.3
    dq = damped_steps(J, e, lam, free)
    for (cols, ek, lk), row, fr in zip(cases, dq, free, strict=True):
        expect = np.zeros(n)
        idx = np.flatnonzero(fr)
        if idx.size:
            expect[idx] = _definition([cols[i] for i in idx], ek, lk)
        np.testing.assert_allclose(row, expect, rtol=1e-7, atol=1e-9)
        np.testing.assert_allclose(dls_step(cols, ek, lk, fr.tolist()), expect, atol=1e-9)
