"""Fitting onto a sheet, cutting at its edge, and the whole plan (shapes, files, planes)."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from drawing_support import EXAMPLES, FakeSheet

from armkit import InputError
from armkit.drawing import (
    DrawingError,
    DrawingWarning,
    Fit,
    PaperSize,
    hausdorff,
    plan_drawing,
    read_drawing,
    shapes,
)

A5 = PaperSize(0.210, 0.148)


def _bounds(plan_strokes: tuple[np.ndarray, ...]) -> tuple[np.ndarray, np.ndarray]:
    pts = np.vstack(plan_strokes)
    return pts.min(axis=0), pts.max(axis=0)


def _aspect(name: str) -> float:
    lo, hi = _bounds(tuple(read_drawing(EXAMPLES / name).flatten(1e-5)))
    return float((hi[0] - lo[0]) / (hi[1] - lo[1]))


def test_fit_fills_the_printable_area_keeping_aspect() -> None:
    plan = plan_drawing(EXAMPLES / "lines.svg", A5, Fit.to_sheet(margin=0.015))
    lo, hi = _bounds(plan.strokes)
    assert np.all(lo >= 0.015 - 1e-9) and np.all(hi <= np.array([0.195, 0.133]) + 1e-9)
    touches = np.isclose(lo, 0.015, atol=1e-9) & np.isclose(hi, [0.195, 0.133], atol=1e-9)
    assert touches.any()  # as large as fits
    assert np.allclose((lo + hi) / 2, [0.105, 0.074], atol=1e-6)  # centred
    assert (hi[0] - lo[0]) / (hi[1] - lo[1]) == pytest.approx(_aspect("lines.svg"), rel=1e-3)
    assert not plan.notes


def test_rotation_stretch_and_real_size() -> None:
    turned = plan_drawing(EXAMPLES / "lines.svg", A5, Fit.to_sheet(rotation=math.pi / 2))
    lo, hi = _bounds(turned.strokes)
    assert (hi[1] - lo[1]) / (hi[0] - lo[0]) == pytest.approx(_aspect("lines.svg"), rel=1e-3)
    stretched = plan_drawing(EXAMPLES / "lines.svg", A5, Fit(None, 0.01, keep_aspect=False))
    lo, hi = _bounds(stretched.strokes)
    assert np.allclose([lo, hi], [[0.01, 0.01], [0.2, 0.138]], atol=1e-6)
    real = plan_drawing(EXAMPLES / "text.svg", PaperSize(0.297, 0.210), Fit(scale=1.0))
    assert real.transform[0, 0] == pytest.approx(1.0)
    with pytest.raises(DrawingError, match="stretches"):
        Fit(scale=2.0, keep_aspect=False)
    with pytest.raises(DrawingError, match="leaves no room"):
        plan_drawing(EXAMPLES / "lines.svg", A5, Fit(margin=0.08))


def test_what_falls_off_the_sheet_is_cut_with_a_note() -> None:
    fig = shapes.figure(shapes.line((0.05, 0.05), (0.30, 0.05)))
    with pytest.warns(DrawingWarning, match=r"cut 100.0 mm of 250.0 mm"):
        plan = plan_drawing(fig, A5, Fit.as_is(margin=0.01))
    (s,) = plan.strokes
    assert np.allclose(s, [[0.05, 0.05], [0.2, 0.05]])
    with pytest.raises(DrawingError, match="outside the sheet"), pytest.warns(DrawingWarning):
        plan_drawing(shapes.figure(shapes.circle((1.0, 1.0), 0.01)), A5, Fit.as_is())


def test_seed_001_shapes_within_tolerance_on_a_tilted_sheet(tilted_a5: FakeSheet) -> None:
    fig = shapes.figure(
        shapes.line((0.03, 0.03), (0.09, 0.03)),
        shapes.line((0.03, 0.04), (0.03, 0.10)),
        shapes.line((0.04, 0.04), (0.09, 0.09)),
        shapes.circle((0.15, 0.07), 0.03),
    )
    plan = plan_drawing(fig, tilted_a5, Fit.as_is(), tolerance=1e-4, start=(0.105, 0.0))
    assert plan.pen_lifts == 4 and plan.pen_down_length == pytest.approx(
        0.06 + 0.06 + 0.05 * math.sqrt(2) + 2 * math.pi * 0.03, rel=1e-3
    )
    exact = [s for s in fig.flatten(1e-8)]
    assert hausdorff(list(plan.strokes), exact, spacing=1e-5) <= 1e-4 + 1e-5
    world = plan.world_strokes(tilted_a5)
    circle = max(world, key=len)
    centre = tilted_a5.to_world(np.array([[0.15, 0.07]]))[0]
    assert np.allclose(np.linalg.norm(circle - centre, axis=1), 0.03, atol=1e-4)
    normal = np.cross(tilted_a5.u, tilted_a5.v)
    assert np.allclose((circle - tilted_a5.origin) @ normal, 0.0, atol=1e-12)


def test_tolerance_budget_holds_for_svg_curves() -> None:
    fig = read_drawing(EXAMPLES / "curve.svg")
    plan = plan_drawing(fig, A5, Fit(), tolerance=2e-4)
    exact = [s @ plan.transform[:2, :2].T + plan.transform[:2, 2] for s in fig.flatten(1e-6)]
    assert hausdorff(list(plan.strokes), exact, spacing=5e-5) <= 2e-4 + 5e-5


def test_files_are_told_apart_by_suffix(tmp_path: Path) -> None:
    assert len(plan_drawing(EXAMPLES / "seed001.gcode", A5, Fit.as_is()).strokes) == 4
    with pytest.raises(DrawingError, match=r"\.svg or a G-code file"):
        read_drawing(tmp_path / "x.dxf")
    with pytest.raises(DrawingError, match=r"must be a file path \(str or Path\), got 5"):
        read_drawing(5)  # type: ignore[arg-type]
    (tmp_path / "empty.gcode").write_text("G0 X1\n")
    with pytest.raises(DrawingError, match="nothing to draw"):
        plan_drawing(tmp_path / "empty.gcode", A5)
    with pytest.raises(DrawingError, match="tolerance"):
        plan_drawing(EXAMPLES / "seed001.gcode", A5, tolerance=0.0)


@pytest.mark.parametrize(
    ("width", "height", "said"),
    [
        (-1.0, 0.2, "PaperSize width .* got -1 m \\(-1000.0 mm\\)"),
        (0.2, 0.0, "PaperSize height .* got 0 m"),
        (210.0, 148.0, "at most 10000 mm, given in metres .* got 210 m \\(210000.0 mm\\)"),
        (float("nan"), 0.2, "width .* got nan$"),
        (0.2, float("inf"), "height .* got inf$"),
        ("a4", 0.2, "width .* got 'a4'"),
        (True, 0.2, "width .* got True"),
    ],
)
def test_paper_size_is_refused_when_made(width: object, height: object, said: str) -> None:
    with pytest.raises(InputError, match=f"{said}") as e:
        PaperSize(width, height)  # type: ignore[arg-type]
    assert "A5 is PaperSize(0.148, 0.210)" in str(e.value) and "\n" not in str(e.value)


def test_paper_size_keeps_good_sizes() -> None:
    assert PaperSize(0.148, 0.210).width == 0.148 and PaperSize(10.0, 1e-3).height == 1e-3
