"""Strokes: merging, simplifying and ordering (properties with fixed seeds)."""

from __future__ import annotations

import itertools

import numpy as np
import pytest
from hypothesis import given, seed, settings
from hypothesis import strategies as st

from armkit.drawing import (
    distance_to_strokes,
    merge_strokes,
    order_strokes,
    pen_up_length,
    simplify,
)
from armkit.drawing._grid import cell_pairs
from armkit.drawing._order import greedy_order


def _key(s: np.ndarray) -> tuple[float, ...]:
    """A stroke's identity whichever way it is drawn."""
    a, b = tuple(np.round(s.ravel(), 12)), tuple(np.round(s[::-1].ravel(), 12))
    return min(a, b)


def test_merge_joins_chains_whichever_way_they_point() -> None:
    a, b, c = (
        np.array([[0.0, 0], [1, 0]]),
        np.array([[2.0, 0], [1, 0]]),
        np.array([[-1.0, 0], [0, 0]]),
    )
    far = np.array([[5.0, 5], [6, 6]])
    merged = merge_strokes([a, b, far, c], 1e-6)
    assert len(merged) == 2
    assert np.allclose(merged[0], [[-1, 0], [0, 0], [1, 0], [2, 0]])
    assert len(merge_strokes([a, b + np.array([0, 1e-3])], 1e-4)) == 2


@seed(1)
@settings(max_examples=60, deadline=None)
@given(st.integers(3, 200), st.floats(1e-5, 1e-2), st.integers(0, 2**31))
def test_simplify_stays_within_tolerance(n: int, tol: float, rng_seed: int) -> None:
    rng = np.random.default_rng(rng_seed)
    s = np.cumsum(rng.normal(0, 1e-3, (n, 2)), axis=0)
    (out,) = simplify([s], tol)
    assert np.array_equal(out[0], s[0]) and np.array_equal(out[-1], s[-1])
    assert distance_to_strokes(s, [out]).max() <= tol * (1 + 1e-9)
    assert len(out) <= n


def test_order_keeps_every_stroke_and_beats_greedy() -> None:
    rng = np.random.default_rng(7)
    for n in (1, 2, 5, 40, 400):
        strokes = [np.cumsum(rng.normal(0, 0.01, (3, 2)), axis=0) + rng.random(2) for _ in range(n)]
        out = order_strokes(strokes)
        assert sorted(map(_key, out)) == sorted(map(_key, strokes))
        heads, tails = np.array([s[0] for s in strokes]), np.array([s[-1] for s in strokes])
        o, f = greedy_order(heads, tails, None)
        greedy = [strokes[i][::-1] if r else strokes[i] for i, r in zip(o, f, strict=True)]
        assert pen_up_length(out) <= pen_up_length(greedy) + 1e-12
        assert pen_up_length(out) <= pen_up_length(strokes) + 1e-12


def test_order_finds_the_best_tour_of_small_drawings() -> None:
    rng = np.random.default_rng(3)
    for _ in range(20):
        strokes = [rng.random((2, 2)) for _ in range(5)]
        best = min(
            pen_up_length(
                [strokes[i][::-1] if (m >> k) & 1 else strokes[i] for k, i in enumerate(p)]
            )
            for p in itertools.permutations(range(5))
            for m in range(32)
        )
        assert pen_up_length(order_strokes(strokes)) <= best * 1.05 + 1e-12


def test_order_solves_a_shuffled_dashed_line_exactly() -> None:
    rng = np.random.default_rng(5)
    dashes = [np.array([[2.0 * i, 0], [2.0 * i + 1, 0]]) for i in range(300)]
    shuffled = [d[::-1] if rng.random() < 0.5 else d for d in rng.permutation(np.array(dashes))]
    assert pen_up_length(order_strokes(list(shuffled))) == pytest.approx(299.0)


def test_start_counts_and_closed_strokes_are_entered_where_nearest() -> None:
    square = np.array([[0.0, 0], [1, 0], [1, 1], [0, 1], [0, 0]])
    (out,) = order_strokes([square], start=np.array([1.2, 1.1]))
    assert np.allclose(out[0], [1, 1]) and np.allclose(out[-1], [1, 1])
    assert pen_up_length([out], np.array([1.2, 1.1])) == pytest.approx(np.hypot(0.2, 0.1))


def test_a_pile_of_copies_of_one_line_merges_in_bounded_pairs() -> None:
    """20,000 copies of one line (found by the fuzzer: every end paired with every other,
    400 million pairs, MemoryError): each end gets at most ``most`` partners per cell."""
    line = np.array([[0.0, 0.0], [0.01, 0.0]])
    ends = np.vstack([line] * 20_000)
    q, _ = cell_pairs(ends, ends, 1e-4, most=32)
    assert len(q) <= len(ends) * 9 * 32
    merged = merge_strokes([line] * 20_000, 1e-4)
    assert sum(len(s) - 1 for s in merged) == 20_000  # every segment drawn once
    assert len(merged) < 20_000  # and joined where ends meet
