"""docs/limits.md lists every input limit with the value the code has (issue 33):
each row's constant, read from the module the row names, equals the limit the row
states, and every limit of ``armkit._input_limits`` has its row."""

from __future__ import annotations

import importlib
import re
from pathlib import Path

import pytest

import armkit._input_limits as input_limits

PAGE = Path(__file__).resolve().parents[1] / "docs" / "limits.md"
ROW = re.compile(
    r"^\|(?P<what>[^|]+)\|(?P<limit>[^|]+)\| `(?P<name>[A-Z_]+)` \| `(?P<module>[\w.]+)` \|$"
)
VALUE = re.compile(r"^\s*(?P<number>\d[\d,]*(?:\.\d+)?(?:e-?\d+)?)\s*(?P<unit>kB|MB)?\b")
UNITS = {None: 1, "kB": 1_000, "MB": 1_000_000}
HELPERS = {"KB", "MB"}  # units, not limits


def _rows() -> list[tuple[str, str, str]]:
    found = [ROW.match(line) for line in PAGE.read_text().splitlines()]
    return [(m["name"], m["module"], m["limit"]) for m in found if m]


def _stated(limit: str) -> float:
    """The number a row's limit column starts with, in the constant's units."""
    m = VALUE.match(limit)
    assert m, f"the limit {limit!r} does not start with its value"
    return float(m["number"].replace(",", "")) * UNITS[m["unit"]]


@pytest.mark.parametrize(("name", "module", "limit"), _rows(), ids=[r[0] for r in _rows()])
def test_each_row_states_the_code_s_value(name: str, module: str, limit: str) -> None:
    value = getattr(importlib.import_module(module), name)
    assert isinstance(value, int | float)
    assert _stated(limit) == value, (
        f"docs/limits.md says {limit.strip()!r}, {module}.{name} = {value}"
    )


def test_every_input_limit_has_its_row() -> None:
    rows = {(name, module) for name, module, _ in _rows()}
    limits = {
        (name, input_limits.__name__)
        for name, value in vars(input_limits).items()
        if name.isupper() and name not in HELPERS and isinstance(value, int | float)
    }
    assert limits - rows == set(), "limits missing from docs/limits.md"
    assert len(rows) == len(_rows()), "a constant listed twice"
