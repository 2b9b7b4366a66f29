"""Tokens and units: numbers with units attached or apart, strings, comments."""

from __future__ import annotations

import math

import pytest

from armkit.script._lexer import LexError, tokenize
from armkit.script._units import UnitProblem, to_si


def test_tokens_keep_columns_and_units() -> None:
    toks = tokenize('  wait 1.5s  # rest\ndraw "my cat.svg"')
    assert [(t.kind, t.text, t.col) for t in toks] == [("word", "wait", 3), ("number", "1.5s", 8)]
    assert toks[1].value == 1.5 and toks[1].unit == "s"
    s = tokenize('draw "my cat.svg" on A5')
    assert s[1].kind == "string" and s[1].text == "my cat.svg" and s[2].col == 19


def test_punctuation_and_negative_numbers() -> None:
    toks = tokenize("define dip(p, depth)")
    assert [t.text for t in toks] == ["define", "dip", "(", "p", ",", "depth", ")"]
    n = tokenize("pitch -90deg")[1]
    assert n.value == -90 and n.unit == "deg"


def test_unclosed_string_names_its_column() -> None:
    with pytest.raises(LexError) as info:
        tokenize('draw "cat.svg')
    assert info.value.col == 6


@pytest.mark.parametrize(
    ("value", "unit", "dim", "si"),
    [
        (20, None, "length", 0.020),
        (2, "cm", "length", 0.020),
        (1, "in", "length", 0.0254),
        (90, None, "angle", math.pi / 2),
        (1, "rad", "angle", 1.0),
        (250, "ms", "time", 0.25),
        (1.5, None, "time", 1.5),
        (50, "%", "percent", 0.5),
        (40, "mm/s", "speed", 0.04),
        (3, None, "count", 3),
    ],
)
def test_units_convert_to_si(value: float, unit: str | None, dim: str, si: float) -> None:
    assert to_si(value, unit, dim) == pytest.approx(si)  # type: ignore[arg-type]


def test_wrong_and_unknown_units_say_what_is_allowed() -> None:
    with pytest.raises(UnitProblem, match=r"2s is a time, but an angle is needed \(deg, rad\)"):
        to_si(2, "s", "angle")
    with pytest.raises(UnitProblem, match="unknown unit 'mn'; a length takes mm, cm, m, in"):
        to_si(2, "mn", "length")
    with pytest.raises(UnitProblem, match="whole number"):
        to_si(2.5, None, "count")
