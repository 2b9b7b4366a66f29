"""Fuzzing the SVG and G-code readers (bounded, fixed seeds): whatever the bytes,
either a drawing or a DrawingError that names the file and the line."""

from __future__ import annotations

import contextlib
import warnings
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, seed, settings
from hypothesis import strategies as st

from armkit.drawing import DrawingError, Fit, PaperSize, plan_drawing, read_gcode, read_svg
from budget import cases

FUZZ = settings(
    max_examples=cases(full=300, quick=100),
    deadline=None,
    suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow],
)
NUMBER = st.one_of(
    st.integers(-500, 500).map(str),
    st.floats(-1e4, 1e4, allow_nan=False).map(lambda v: f"{v:.3f}"),
    st.sampled_from(["", "-", ".", "1e3", "1e400", "9" * 30, "+.5", "0"]),
)
G_WORD = st.tuples(
    st.sampled_from([*list("GMXYZIJFPSNRTEgx"), "", "*", "#"]),
    NUMBER,
).map("".join)
G_KNOWN = st.sampled_from(
    [
        "G0",
        "G1",
        "G2",
        "G3",
        "G4 P0.1",
        "G20",
        "G21",
        "G90",
        "G91",
        "G28",
        "M3",
        "M5",
        "M300 S30",
        "M300 S50",
        "M2",
    ]
)
G_LINE = st.lists(
    st.one_of(G_KNOWN, G_WORD, st.sampled_from(["(c)", "; c", "(", ")", "%", "\t", "\x0c"])),
    max_size=6,
).map(" ".join)


def _check(e: DrawingError, path: Path) -> None:
    assert e.file == str(path)
    assert e.line is not None and e.line >= 1 and e.column is not None and e.column >= 1
    assert str(e).startswith(f"{path} line {e.line} column {e.column}: ")
    assert isinstance(e, ValueError)


@seed(2026)
@FUZZ
@given(st.lists(G_LINE, min_size=1, max_size=25))
def test_gcode_fuzz(tmp_path: Path, lines: list[str]) -> None:
    path = tmp_path / "fuzz.gcode"
    path.write_text("\n".join(lines), encoding="utf-8")
    try:
        fig = read_gcode(path)
    except DrawingError as e:
        _check(e, path)
        return
    if fig.paths:
        with contextlib.suppress(DrawingError):  # e.g. too many points: named, not a crash
            plan_drawing(fig, PaperSize(0.2, 0.2), Fit())


@seed(2026)
@FUZZ
@given(st.binary(max_size=300))
def test_gcode_fuzz_bytes(tmp_path: Path, data: bytes) -> None:
    path = tmp_path / "bytes.nc"
    path.write_bytes(data)
    try:
        read_gcode(path)
    except DrawingError as e:
        _check(e, path)


PATH_DATA = st.lists(
    st.one_of(st.sampled_from([*list("MmLlHhVvCcSsQqTtAaZz,  "), "x", "e", "1e", "--"]), NUMBER),
    max_size=25,
).map(" ".join)
TRANSFORM = st.lists(
    st.tuples(
        st.sampled_from(["matrix", "translate", "scale", "rotate", "skewX", "skewY", "spin", ""]),
        st.lists(NUMBER, max_size=7).map(lambda v: "(" + ",".join(v) + ")"),
    ).map("".join),
    max_size=3,
).map(" ".join)
ATTRS = st.fixed_dictionaries(
    {},
    optional={
        "d": PATH_DATA,
        "transform": TRANSFORM,
        "points": st.lists(NUMBER, max_size=8).map(" ".join),
        "r": NUMBER,
        "cx": NUMBER,
        "width": st.tuples(NUMBER, st.sampled_from(["", "mm", "px", "%", "in", "em", "q"])).map(
            "".join
        ),
        "height": NUMBER,
        "rx": NUMBER,
        "viewBox": st.lists(NUMBER, max_size=5).map(" ".join),
        "style": st.sampled_from(["display:none", "stroke:red", ";;", "display"]),
    },
)
ELEMENT = st.tuples(
    st.sampled_from(
        [
            "path",
            "rect",
            "circle",
            "ellipse",
            "line",
            "polyline",
            "polygon",
            "g",
            "text",
            "use",
            "svg",
        ]
    ),
    ATTRS,
)


def _svg(elements: list[tuple[str, dict[str, str]]], junk: list[tuple[int, str]]) -> str:
    body = "".join(
        f"<{tag} " + " ".join(f'{k}="{v}"' for k, v in attrs.items()) + "/>\n"
        for tag, attrs in elements
    )
    text = f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100">\n{body}</svg>\n'
    for at, chars in junk:
        k = at % (len(text) + 1)
        text = text[:k] + chars + text[k:]
    return text


@seed(2026)
@FUZZ
@given(
    st.lists(ELEMENT, max_size=6),
    st.lists(
        st.tuples(
            st.integers(0, 10_000),
            st.sampled_from(["<", ">", '"', "&", "\n", "x", "/", "=", "<!--"]),
        ),
        max_size=2,
    ),
)
def test_svg_fuzz(
    tmp_path: Path, elements: list[tuple[str, dict[str, str]]], junk: list[tuple[int, str]]
) -> None:
    path = tmp_path / "fuzz.svg"
    path.write_text(_svg(elements, junk), encoding="utf-8")
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            fig = read_svg(path)
    except DrawingError as e:
        _check(e, path)
        return
    if fig.paths:
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                plan_drawing(fig, PaperSize(0.2, 0.2), Fit())
        except DrawingError:
            pass


@pytest.mark.parametrize(
    "data",
    [b"\xff\xfe<svg", b"<svg xmlns='http://www.w3.org/2000/svg'><path d='M 0 0 L \x00'/></svg>"],
)
def test_svg_bytes_that_are_not_text(tmp_path: Path, data: bytes) -> None:
    path = tmp_path / "b.svg"
    path.write_bytes(data)
    with pytest.raises(DrawingError) as e:
        read_svg(path)
    _check(e.value, path)
