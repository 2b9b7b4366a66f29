"""SVG input: shapes, transforms and viewBox in metres; problems with line and column."""

from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np
import pytest
from drawing_support import EXAMPLES, write

from armkit.drawing import DrawingError, DrawingWarning, read_svg

HEAD = '<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="50mm" viewBox="0 0 200 100">'


def _svg(tmp_path: Path, body: str) -> Path:
    return write(tmp_path, "t.svg", f"{HEAD}\n{body}\n</svg>\n")


def test_viewbox_scales_to_millimetres_and_flips_y(tmp_path: Path) -> None:
    fig = read_svg(_svg(tmp_path, '<line x1="0" y1="0" x2="200" y2="100"/>'))
    (s,) = fig.flatten(1e-4)
    assert np.allclose(s * 1e3, [[0, 0], [100, -50]], atol=1e-3)


def test_transforms_and_basic_shapes(tmp_path: Path) -> None:
    body = (
        '<g transform="translate(100 50) rotate(90)"><rect x="0" y="0" width="20" height="10"/></g>'
        '<circle cx="20" cy="20" r="10"/><polygon points="0,0 10,0 10,10"/>'
        '<ellipse cx="50" cy="50" rx="20" ry="10"/><polyline points="0,0 1,1"/>'
    )
    fig = read_svg(_svg(tmp_path, body))
    rect, circle, polygon, ellipse, polyline = fig.flatten(1e-5)
    # the rectangle turned 90 degrees about (100, 50) user units = (50, -25) mm
    assert np.allclose(np.sort(rect * 1e3, axis=0)[[0, -1]], [[45, -35], [50, -25]], atol=1e-3)
    r = np.linalg.norm(circle * 1e3 - [10, -10], axis=1)
    assert np.allclose(r, 5.0, atol=0.01)
    assert np.allclose(polygon[0], polygon[-1])  # closed
    e = (ellipse * 1e3 - [25, -25]) / [10, 5]
    assert np.allclose(np.hypot(*e.T), 1.0, atol=1e-3)
    assert len(polyline) == 2


def test_path_commands_within_tolerance(tmp_path: Path) -> None:
    body = '<path d="M 0 0 C 0 50 100 50 100 0 Q 150 -50 200 0 A 50 25 0 0 1 100 50 z"/>'
    fig = read_svg(_svg(tmp_path, body))
    coarse, fine = fig.flatten(1e-4)[0], fig.flatten(1e-7)[0]
    from armkit.drawing import hausdorff

    assert hausdorff([coarse], [fine], spacing=1e-5) <= 1e-4 + 1e-5
    assert np.allclose(coarse[0], coarse[-1])


def test_hidden_elements_and_text(tmp_path: Path) -> None:
    body = (
        '<line x1="0" y1="0" x2="1" y2="1" style="display:none"/>'
        '<line x1="0" y1="0" x2="1" y2="1" visibility="hidden"/>'
        '\n<text x="0" y="10">hello</text><line x1="0" y1="0" x2="9" y2="9"/>'
    )
    with pytest.warns(DrawingWarning, match=r"1 text element\(s\) left out \(line 3\)"):
        fig = read_svg(_svg(tmp_path, body))
    assert len(fig.paths) == 1
    assert "Object to Path" in fig.notes[0]
    with pytest.warns(DrawingWarning, match=r"1 image element\(s\) left out"):
        read_svg(_svg(tmp_path, '<image href="x.png" width="5" height="5"/><line x2="1"/>'))


@pytest.mark.parametrize(
    ("body", "line", "column", "what"),
    [
        ('<path d="M 10 10 L 20 Q"/>', 2, 23, "a number in 'L'"),
        ('<path\n   d="M 1 1 x 3"/>', 3, 13, "in 'M'"),
        ('<path d="10 10"/>', 2, 10, "start with M"),
        ('<path d="M0 0 a 1 1 0 2 1 5 5"/>', 2, 23, "arc flag"),
        ('<g transform="rotate(foo)"/>', 2, 22, "1 or 3 numbers in rotate"),
        ('<g transform="spin(3)"/>', 2, 15, "a transform"),
        ('<circle cx="1" cy="1" r="-3"/>', 2, 26, "a length >= 0"),
        ('<rect width="1e400" height="1"/>', 2, 14, "at most"),
        ('<polyline points="1,2 3"/>', 2, 24, "odd count"),
        ("<line x1='0' y1='0' x2='1' y2='1'>", 3, 3, "not well-formed"),
        ('<svg x="9" viewBox="0 0 1 1"><rect width="1" height="1"/></svg>', 2, 1, "nested <svg>"),
    ],
)
def test_errors_name_file_line_and_column(
    tmp_path: Path, body: str, line: int, column: int, what: str
) -> None:
    path = _svg(tmp_path, body)
    with pytest.raises(DrawingError, match=what) as e:
        read_svg(path)
    assert (e.value.file, e.value.line, e.value.column) == (str(path), line, column)
    assert str(e.value).startswith(f"{path}:{line}:{column}: ")
    assert isinstance(e.value, ValueError)


def test_not_an_svg_and_missing_file(tmp_path: Path) -> None:
    with pytest.raises(DrawingError, match=r":1:1: the root element is <html>"):
        read_svg(write(tmp_path, "x.svg", "<html><body/></html>"))
    with pytest.raises(DrawingError, match=r":1:1: not well-formed XML \(no element"):
        read_svg(write(tmp_path, "e.svg", ""))
    with pytest.raises(DrawingError, match="cannot read the drawing"):
        read_svg(tmp_path / "missing.svg")


def test_example_drawings_read_without_warnings() -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        for name in ("lines.svg", "text.svg", "curve.svg"):
            assert read_svg(EXAMPLES / name).paths


def test_an_element_svgelements_chokes_on_is_found_alone(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    import armkit.drawing._svg as svg_module

    real = svg_module._element_paths

    def choke_on_ellipses(element, se):  # type: ignore[no-untyped-def]
        if isinstance(element, se.Ellipse):
            raise TypeError("boom")
        return real(element, se)

    monkeypatch.setattr(svg_module, "_element_paths", choke_on_ellipses)
    path = _svg(tmp_path, '<circle r="3"/>\n  <ellipse rx="3" ry="2"/>')
    with pytest.raises(DrawingError, match=r":3:3: svgelements cannot read <ellipse>"):
        read_svg(path)
