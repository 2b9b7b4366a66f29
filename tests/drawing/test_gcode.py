"""G-code input: moves, arcs, units, modes, pen by Z / M3-M5 / M300; errors with line and column."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from drawing_support import EXAMPLES, write

from armkit.drawing import DrawingError, read_gcode


def _strokes(tmp_path: Path, text: str, **kw: float) -> list[np.ndarray]:
    return [s * 1e3 for s in read_gcode(write(tmp_path, "t.gcode", text), **kw).flatten(1e-6)]


def test_seed_001_three_lines_and_a_circle() -> None:
    fig = read_gcode(EXAMPLES / "seed001.gcode")
    h, v, d, c = (s * 1e3 for s in fig.flatten(1e-5))
    assert np.allclose(h, [[10, 10], [70, 10]]) and np.allclose(v, [[10, 20], [10, 80]])
    assert np.allclose(d, [[20, 20], [70, 70]])
    assert np.allclose(np.linalg.norm(c - [95, 50], axis=1), 25, atol=1e-3)
    assert np.allclose(c[0], c[-1]) and fig.dwell == pytest.approx(0.5)


def test_pen_by_z_threshold_and_relative_inches(tmp_path: Path) -> None:
    text = "G20 G91\nG0 X1 Y1\nG1 Z-0.1\nG1 X1\nY1\nG0 Z0.2\nX1\n"
    (s,) = _strokes(tmp_path, text)
    assert np.allclose(s, [[25.4, 25.4], [50.8, 25.4], [50.8, 50.8]])
    assert len(_strokes(tmp_path, "G1 Z1\nG1 X5\nG1 Z0.5\nX9", z_down=0.6e-3)) == 1


def test_m3_m5_and_m300_move_the_pen_and_then_z_does_not(tmp_path: Path) -> None:
    a, b = _strokes(tmp_path, "G0 X1\nM3 S1000\nG1 X2 Z5\nM5\nG0 X3\nM300 S30\nG1 Y4\nM300 S50")
    assert np.allclose(a, [[1, 0], [2, 0]]) and np.allclose(b, [[3, 0], [3, 4]])


def test_arcs_turn_the_right_way(tmp_path: Path) -> None:
    (cw,) = _strokes(tmp_path, "G1 Z-1\nG2 X10 Y0 I5 J0")  # clockwise from (0,0): over the top
    (ccw,) = _strokes(tmp_path, "G1 Z-1\nG3 X10 Y0 I5 J0")
    assert cw[:, 1].max() == pytest.approx(5, abs=1e-3) and ccw[:, 1].min() == pytest.approx(
        -5, abs=1e-3
    )


def test_dot_g28_and_program_end(tmp_path: Path) -> None:
    dot, lowered = _strokes(
        tmp_path, "G0 X5 Y5\nG1 Z-1\nG1 Z1\nG1 X9 Z-1\nG28\nG1 X20\nM30\nG1 X99"
    )
    assert np.allclose(dot, [[5, 5], [5, 5]])
    assert np.allclose(lowered, [[9, 5], [9, 5]])  # G28 lifted the pen: X20 drew nothing


@pytest.mark.parametrize(
    ("text", "line", "column", "what"),
    [
        ("G21\nG1 X1 T2", 2, 7, "T2 is not supported"),
        ("G1 X1\n  G92 X0", 2, 3, "G92 is not supported"),
        ("G1 X1 X2", 1, 7, "X is given twice"),
        ("G1 E5", 1, 4, "3D printer"),
        ("G2 X1 R5", 1, 7, "I and J"),
        ("G0 G1 X1", 1, 4, "on one line"),
        ("X1 Y1", 1, 1, "before any G0"),
        ("G1 X1 (never closed", 1, 7, r"comment '\(' is not closed"),
        ("G1 X1 *23", 1, 7, "checksums"),
        ("G1 X#1", 1, 4, "not followed by a number"),
        ("G1 X1\nG2 X10 Y0", 2, 1, "needs the arc centre"),
        ("G1 Z-1\nG2 X10 Y3 I5", 2, 1, "from the centre"),
        ("M300 S40", 1, 6, "S30"),
        ("G4", 1, 1, "G4 needs a pause"),
        ("G1 I3", 1, 4, "only for arcs"),
        ("G1 X1e30", 1, 4, r"X1e30: G-code numbers have no exponent; write the value in plain"),
        ("G1 Y-2.5E+3", 1, 4, r"Y-2.5E\+3: G-code numbers have no exponent"),
        ("G1 X" + "9" * 400, 1, 4, r"X9+\.\.\. is out of range; .* at most 1000000$"),
        ("G1 F2000000", 1, 4, r"F2000000 is out of range"),
    ],
)
def test_errors_name_file_line_and_column(
    tmp_path: Path, text: str, line: int, column: int, what: str
) -> None:
    path = write(tmp_path, "bad.nc", text)
    with pytest.raises(DrawingError, match=what) as e:
        read_gcode(path)
    assert (e.value.line, e.value.column) == (line, column)
    assert str(e.value).startswith(f"{path}:{line}:{column}: ")
