"""The single-matrix rotation check (``_inputs._is_rotation``, plain floats: the input
check cost more than the compiled LM solve itself on a full-pose ik call) accepts and
refuses exactly what the batch check (numpy, ``np.allclose`` + determinant) does, on
rotations, rotations perturbed around the tolerance, reflections and scalings."""

from __future__ import annotations

import numpy as np
import pytest

from armkit._errors import InputError
from armkit._inputs import rotation


def _random_rotations(rng: np.random.Generator, n: int) -> np.ndarray:
    q, _ = np.linalg.qr(rng.normal(size=(n, 3, 3)))
    return q * np.sign(np.linalg.det(q))[:, None, None]


def test_one_matrix_is_judged_as_in_a_batch() -> None:
    rng = np.random.default_rng(33)
    R = _random_rotations(rng, 4000)
    scale = 10.0 ** rng.uniform(-8, -4, (4000, 1, 1))  # around the 1e-6 / 1.1e-5 limits
    cases = np.concatenate(
        [
            R,
            R + scale * rng.normal(size=(4000, 3, 3)),
            R * (1.0 + scale),
            -R,  # determinant -1
            R[:, :, [1, 0, 2]],  # a reflection: two columns swapped
        ]
    )
    accepted = refused = 0
    for M in cases:
        try:
            rotation(M[None], "R", 1)
            batch = True
        except InputError:
            batch = False
        try:
            rotation(M, "R")
            one = True
        except InputError:
            one = False
        assert one == batch, M
        accepted += one
        refused += not one
    assert accepted > 4000 and refused > 8000  # both sides of the line are exercised


def test_a_singular_or_non_finite_matrix_is_refused() -> None:
    for M in (np.zeros((3, 3)), np.full((3, 3), np.nan), np.eye(3) * 2.0):
        with pytest.raises(InputError):
            rotation(M, "R")
