"""Comparing a pen trace with the plan, and the pictures of both."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from drawing_support import EXAMPLES, FakeSheet

from armkit import InputError
from armkit.drawing import (
    DrawingError,
    Fit,
    PenTrace,
    check_picture_path,
    measure,
    plan_drawing,
    preview,
    result,
)
from armkit.drawing._distance import sample


def _trace(plan, sheet: FakeSheet, offset=(0.0, 0.0), drop: int | None = None) -> PenTrace:  # type: ignore[no-untyped-def]
    """The pen following the plan at 1 mm steps, lifted 5 mm between strokes."""
    normal = np.cross(sheet.u, sheet.v)
    pts, down = [], []
    for k, s in enumerate(plan.strokes):
        if k == drop:
            continue
        w = sheet.to_world(sample([s], 1e-3) + offset)
        lifted = w[[0, -1]] + 0.005 * normal
        pts += [lifted[:1], w, lifted[1:]]
        down += [[False], [True] * len(w), [False]]
    p = np.vstack(pts)
    return PenTrace(np.arange(len(p)) * 0.01, p, np.concatenate(down).astype(bool))


def test_a_faithful_trace_scores_zero(tilted_a5: FakeSheet) -> None:
    plan = plan_drawing(EXAMPLES / "seed001.gcode", tilted_a5, Fit.as_is())
    m = measure(plan, _trace(plan, tilted_a5), tilted_a5)
    assert m.hausdorff < 1e-6 and m.rms_cross_track < 1e-6
    assert m.pen_down_length == pytest.approx(plan.pen_down_length, rel=1e-3)
    assert m.pen_lifts == 4
    assert m.pen_up_length == pytest.approx(plan.pen_up_length + 8 * 0.005, rel=1e-6)
    assert "Hausdorff 0.00 mm" in str(m)


def test_an_offset_and_a_missing_stroke_show(tilted_a5: FakeSheet) -> None:
    plan = plan_drawing(EXAMPLES / "seed001.gcode", tilted_a5, Fit.as_is())
    m = measure(plan, _trace(plan, tilted_a5, offset=(3e-4, 0.0)), tilted_a5)
    assert m.hausdorff == pytest.approx(3e-4, abs=2e-5)
    assert 1e-4 < m.rms_cross_track <= 3e-4 + 1e-9
    missing = max(range(4), key=lambda k: len(plan.strokes[k]))  # the circle
    m = measure(plan, _trace(plan, tilted_a5, drop=missing), tilted_a5)
    assert m.hausdorff > 0.02 and m.pen_lifts == 3


def test_bad_traces_are_refused(tilted_a5: FakeSheet) -> None:
    with pytest.raises(DrawingError, match="must not decrease"):
        PenTrace(np.array([1.0, 0.0]), np.zeros((2, 3)), np.array([True, True]))
    plan = plan_drawing(EXAMPLES / "seed001.gcode", tilted_a5, Fit.as_is())
    with pytest.raises(DrawingError, match="never touches"):
        measure(plan, PenTrace(np.zeros(2), np.ones((2, 3)), np.zeros(2, bool)), tilted_a5)


def test_pictures_at_the_sheets_real_size(tmp_path: Path, tilted_a5: FakeSheet) -> None:
    from matplotlib.image import imread

    plan = plan_drawing(EXAMPLES / "lines.svg", tilted_a5, Fit(), start=(0.105, 0.0))
    a = imread(preview(plan, tmp_path / "plan.png", dpi=100))
    b = imread(result(plan, _trace(plan, tilted_a5), tilted_a5, tmp_path / "drawn.png", dpi=100))
    assert a.shape[:2] == b.shape[:2]
    assert np.allclose(a.shape[:2], (148 / 25.4 * 100, 210 / 25.4 * 100), atol=1)
    assert (a[..., :3].min(axis=2) < 0.5).mean() > 0.005  # ink on the page
    with pytest.raises(InputError, match=r"\.png, \.svg, \.pdf"):
        check_picture_path(tmp_path / "plan.jpg")
    with pytest.raises(InputError, match="does not exist"):
        check_picture_path(tmp_path / "no" / "plan.png")


def test_import_loads_no_plotting_or_svg_library() -> None:
    import subprocess
    import sys

    code = "import sys, armkit.drawing; print(sorted(m for m in ('matplotlib', 'svgelements', 'scipy') if m in sys.modules))"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "[]"
