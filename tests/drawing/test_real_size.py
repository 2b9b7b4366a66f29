"""Drawings at the size the file gives (issue 28, item 3): a 40 mm SVG circle was
drawn 128 mm wide (every drawing was scaled to fill the sheet) and seed 001's G-code
x1.16. Now a file is drawn at its real size (its units, viewBox and width/height),
centred on the sheet, refused with its size if it does not fit; ``fit`` (``--fit``,
the script's ``fit``) scales it to the sheet. The circle's width is measured from the
simulator's pen trace, not from armkit's plan."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from armkit import Arm
from armkit.drawing import DrawingError, PaperSize, draw, ink, plan_drawing
from armkit.scene import load_scene
from armkit.script import Source, parse
from armkit.script._ast import Job
from armkit.sim import World

EXAMPLES = Path(__file__).parents[2] / "examples" / "drawings"
A5 = PaperSize(0.148, 0.210)  # the shipped sheet: portrait


def _circle(tmp_path: Path, root: str, circle: str, name: str = "circle.svg") -> Path:
    p = tmp_path / name
    p.write_text(
        f'<svg xmlns="http://www.w3.org/2000/svg" {root}>'
        f'<circle {circle} fill="none" stroke="black"/></svg>'
    )
    return p


def _width(strokes: list[np.ndarray] | tuple[np.ndarray, ...]) -> np.ndarray:
    pts = np.vstack(strokes)
    return np.ptp(pts, axis=0)


@pytest.mark.parametrize(
    "root,circle",
    [
        ('width="40mm" height="40mm" viewBox="0 0 40 40"', 'cx="20" cy="20" r="20"'),
        ('width="4cm" height="4cm" viewBox="0 0 400 400"', 'cx="200" cy="200" r="200"'),
        ('width="1.5748031in" height="1.5748031in"', 'cx="0.7874in" cy="0.7874in" r="0.7874in"'),
        ('width="151.1811" height="151.1811"', 'cx="75.59055" cy="75.59055" r="75.59055"'),
    ],
    ids=["mm-viewbox", "cm-scaled-viewbox", "inches", "css-px"],
)
def test_a_40_mm_circle_is_planned_40_mm_wide_in_any_units(
    tmp_path: Path, root: str, circle: str
) -> None:
    plan = plan_drawing(_circle(tmp_path, root, circle), A5)
    assert np.allclose(_width(plan.strokes), 0.040, atol=2e-4)
    centre = (np.vstack(plan.strokes).min(axis=0) + np.vstack(plan.strokes).max(axis=0)) / 2
    assert np.allclose(centre, [0.074, 0.105], atol=1e-6)  # placed: centred on the sheet


def test_seed_001_gcode_is_drawn_at_its_millimetres() -> None:
    plan = plan_drawing(EXAMPLES / "seed001.gcode", A5)
    assert np.allclose(_width(plan.strokes), [0.110, 0.070], atol=1e-4)  # X 10..120, Y 10..80


def test_too_large_is_refused_with_its_size_and_fit_scales_it(tmp_path: Path) -> None:
    big = _circle(
        tmp_path, 'width="200mm" height="200mm" viewBox="0 0 200 200"', 'cx="100" cy="100" r="100"'
    )
    with pytest.raises(DrawingError) as err:
        plan_drawing(big, A5)
    said = str(err.value)
    assert "the drawing is 200.0 x 200.0 mm" in said and "128 x 190 mm" in said
    assert "--fit" in said and "circle.svg" in said
    fitted = plan_drawing(big, A5, fit=True)
    assert np.allclose(_width(fitted.strokes), 0.128, atol=2e-4)  # the sheet's width less margins


def test_the_shipped_example_drawings_fit_the_shipped_sheet_at_real_size() -> None:
    for name in ("lines.svg", "text.svg", "curve.svg", "seed001.gcode"):
        plan = plan_drawing(EXAMPLES / name, A5)
        assert plan.transform[0, 0] == pytest.approx(1.0), name  # real size, not scaled


def _job_args(text: str) -> dict[str, object]:
    program, problems = parse(Source("t.arm", text))
    assert problems == []
    (job,) = program.statements
    assert isinstance(job, Job)
    return {a.name: a.value for a in job.args}


def test_the_script_writes_fit_as_a_word() -> None:
    assert _job_args("draw square.svg fit on A5\n")["fit"] is True
    assert _job_args("draw square.svg on A5 fit\n")["fit"] is True
    assert "fit" not in _job_args("draw square.svg on A5\n")
    _, problems = parse(Source("t.arm", "draw square.svg fit fit\n"))
    assert problems  # written once


def test_a_40_mm_circle_is_drawn_40_mm_wide_by_the_simulated_pen(tmp_path: Path) -> None:
    svg = _circle(
        tmp_path, 'width="40mm" height="40mm" viewBox="0 0 40 40"', 'cx="20" cy="20" r="20"'
    )
    scene = load_scene("drawing")
    with Arm("openmanipulator_x", "sim", world=World(), scene=scene) as arm:
        job = draw(arm, scene, svg)
    assert job.trace is not None
    drawn = ink(job.trace, job.sheet)
    assert np.allclose(_width(drawn), 0.040, atol=0.6e-3)  # what the pen put on the paper
