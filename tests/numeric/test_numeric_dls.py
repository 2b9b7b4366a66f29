"""The damped least-squares step: the scalar fast variants and the batch form
against the one Cholesky factorisation (``dls_step_reference``), and that
against the definition, dq = argmin |J dq - e|^2 + lam |dq|^2."""

from __future__ import annotations

import numpy as np
import pytest

from armkit.kinematics._numeric._dls import damped_steps, dls_step, dls_step_reference

SIZES = [(m, n) for m in (3, 4, 6) for n in range(2, 7)]


def _case(m: int, n: int, seed: int) -> tuple[list[tuple[float, ...]], list[float], float]:
    rng = np.random.default_rng(seed)
    cols = [tuple(rng.uniform(-1.0, 1.0, m).tolist()) for _ in range(n)]
    return cols, rng.uniform(-1.0, 1.0, m).tolist(), float(10.0 ** rng.uniform(-6.0, 0.0))


@pytest.mark.parametrize(("m", "n"), SIZES)
def test_reference_is_the_damped_least_squares_step(m: int, n: int) -> None:
    for seed in range(10):
        cols, e, lam = _case(m, n, seed)
        J = np.array(cols).T  # (m, n)
        expect = np.linalg.solve(J.T @ J + lam * np.eye(n), J.T @ np.array(e))
        np.testing.assert_allclose(dls_step_reference(cols, e, lam), expect, rtol=1e-7, atol=1e-9)


@pytest.mark.parametrize(("m", "n"), SIZES)
def test_fast_variants_equal_the_reference(m: int, n: int) -> None:
    for seed in range(20):
        cols, e, lam = _case(m, n, seed)
        ref = dls_step_reference(cols, e, lam)
        np.testing.assert_allclose(dls_step(cols, e, lam, None), ref, rtol=1e-7, atol=1e-9)


@pytest.mark.parametrize(("m", "n"), SIZES)
def test_batch_steps_equal_the_reference_frozen_joints_included(m: int, n: int) -> None:
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
            expect[idx] = dls_step_reference([cols[i] for i in idx], ek, lk)
        np.testing.assert_allclose(row, expect, rtol=1e-7, atol=1e-9)
        np.testing.assert_allclose(dls_step(cols, ek, lk, fr.tolist()), expect, atol=1e-9)
