"""Cartesian paths: on the geometry, spacing respected, ends exact."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from armkit.motion import (
    approach,
    arc,
    circle,
    corners,
    cube_edges,
    distance_to_polyline,
    line,
    polyline,
    rectangle,
    retreat,
)

SETTINGS = settings(max_examples=50, derandomize=True, deadline=None)
coord = st.floats(-0.3, 0.3)
point = st.tuples(coord, coord, coord).map(np.array)
spacing = st.floats(0.0005, 0.02)


def _steps(p: np.ndarray) -> np.ndarray:
    return np.linalg.norm(np.diff(p, axis=0), axis=1)


@SETTINGS
@given(point, point, spacing)
def test_line_is_straight_evenly_spaced_and_exact_at_the_ends(a, b, sp) -> None:
    p = line(a, b, sp)
    np.testing.assert_array_equal(p[0], a)
    np.testing.assert_allclose(p[-1], b, atol=1e-15)
    assert np.all(_steps(p) <= sp * (1 + 1e-9))
    np.testing.assert_allclose(_steps(p), _steps(p)[0], atol=1e-12)
    assert np.max(distance_to_polyline(p, np.stack([a, b]))) < 1e-9


@SETTINGS
@given(point, st.floats(0.005, 0.2), st.floats(-4, 4), st.floats(-7, 7), spacing)
def test_arc_points_lie_on_the_circle(c, r, start, sweep, sp) -> None:
    if abs(sweep) < 1e-3:
        sweep = 1.0
    p = arc(c, r, start, sweep, sp)
    np.testing.assert_allclose(np.hypot(p[:, 0] - c[0], p[:, 1] - c[1]), r, rtol=1e-12)
    np.testing.assert_allclose(p[:, 2], c[2])
    assert np.all(_steps(p) <= sp * (1 + 1e-9))
    start_pt = c + r * np.array([math.cos(start), math.sin(start), 0])
    end_pt = c + r * np.array([math.cos(start + sweep), math.sin(start + sweep), 0])
    np.testing.assert_allclose(p[0], start_pt, atol=1e-12)
    np.testing.assert_allclose(p[-1], end_pt, atol=1e-12)


def test_circle_closes_and_turns_counter_clockwise() -> None:
    p = circle([0.2, 0.0, 0.05], 0.05, 0.002)
    np.testing.assert_allclose(p[0], p[-1], atol=1e-12)
    cross = np.cross(p[1] - p[0], p[2] - p[1])
    assert cross[2] > 0
    assert corners(p).size == 0


def test_rectangle_has_four_corners_and_the_right_size() -> None:
    p = rectangle([0.2, 0.0, 0.05], 0.1, 0.06, 0.003)
    np.testing.assert_allclose(p.min(axis=0), [0.15, -0.03, 0.05])
    np.testing.assert_allclose(p.max(axis=0), [0.25, 0.03, 0.05])
    np.testing.assert_allclose(p[0], p[-1])
    assert corners(p).size == 3  # the start/end corner is the path's end, not interior
    assert np.all(_steps(p) <= 0.003 * (1 + 1e-9))


def test_cube_trace_covers_all_twelve_edges() -> None:
    size = 0.04
    p = cube_edges([0.15, -0.02, 0.03], size, 0.002)
    rel = np.round((p - [0.15, -0.02, 0.03]) / size, 9)
    vertices = {tuple(v) for v in rel if np.all(np.isin(v, [0.0, 1.0]))}
    assert len(vertices) == 8
    mids = {tuple(v) for v in np.round(rel * 2) / 2 if np.sum(v == 0.5) == 1}
    assert len(mids) == 12  # one midpoint per edge
    assert np.all(_steps(p) <= 0.002 * (1 + 1e-9))


def test_polyline_rejects_bad_input() -> None:
    with pytest.raises(ValueError, match="vertices"):
        polyline([[0, 0, 0]], 0.01)
    with pytest.raises(ValueError, match="spacing"):
        line([0, 0, 0], [1, 0, 0], 0.0)
    with pytest.raises(ValueError, match="radius"):
        circle([0, 0, 0], -1.0, 0.01)


def test_approach_comes_down_from_30mm_in_three_steps_and_retreat_goes_back() -> None:
    target = np.array([0.2, 0.0, 0.02])
    down = approach(target)
    np.testing.assert_allclose(down[:, 2] - 0.02, [0.03, 0.02, 0.01, 0.0], atol=1e-15)
    np.testing.assert_allclose(down[:, :2], [[0.2, 0.0]] * 4)
    np.testing.assert_allclose(retreat(target), down[::-1])
    with pytest.raises(ValueError, match=">= 30 mm"):
        approach(target, height=0.01)
