"""Only ``Arm`` carries a plan out to a driver (issue 26): ``.driver`` is used in
``armkit.arm``, ``armkit.drivers``, ``armkit.connect`` and ``armkit.sim`` alone; jobs
(tasks, drawing, music, sensing), the script language, the viewer and the CLI plan and ask
``Arm`` to run the plan, never reaching past it."""

from __future__ import annotations

import ast
import re
from pathlib import Path

from import_reader import SRC

ALLOWED = ("arm", "drivers", "connect", "sim")
DOT_DRIVER = re.compile(r"\.driver\b")  # the issue's own rule: grep -rn "\.driver\b"


def _package(path: Path) -> str:
    """The armkit package a module is in (``tasks`` for armkit/tasks/_jobs.py)."""
    parts = path.relative_to(SRC / "armkit").parts
    return parts[0] if len(parts) > 1 else ""


def _outside() -> list[Path]:
    paths = sorted((SRC / "armkit").rglob("*.py"))
    assert len(paths) > 100
    return [path for path in paths if _package(path) not in ALLOWED]


def reaches(source: str) -> list[int]:
    """Lines of ``source`` that reach a driver: ``x.driver`` or ``getattr(x, "driver")``."""
    return sorted(
        node.lineno
        for node in ast.walk(ast.parse(source))
        if (isinstance(node, ast.Attribute) and node.attr == "driver") or _by_name(node)
    )


def _by_name(node: ast.AST) -> bool:
    """``getattr(x, "driver")`` (or setattr, hasattr)."""
    return (
        isinstance(node, ast.Call)
        and ast.unparse(node.func) in ("getattr", "setattr", "hasattr")
        and len(node.args) > 1
        and isinstance(node.args[1], ast.Constant)
        and node.args[1].value == "driver"
    )


def test_the_rule_finds_each_form() -> None:
    source = 'arm.driver.move(q)\nd = getattr(arm, "driver")\narm.driver_name\nx = "a.driver"\n'
    assert reaches(source) == [1, 2]


def test_only_arm_drivers_connect_and_sim_reach_a_driver() -> None:
    found = [
        f"{path.relative_to(SRC)}:{line}"
        for path in _outside()
        for line in reaches(path.read_text(encoding="utf-8"))
    ]
    assert found == []


def test_no_text_outside_them_says_dot_driver() -> None:
    # the grep, docstrings and comments included
    found = [
        f"{path.relative_to(SRC)}:{number}: {line.strip()}"
        for path in _outside()
        for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1)
        if DOT_DRIVER.search(line)
    ]
    assert found == []
