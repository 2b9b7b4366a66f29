"""Nothing of armkit is imported by a string (issue 26): no ``importlib.import_module``,
no ``__import__``, no ``"module:function"`` table. Jobs, driver kinds, command modules
and scene kinds are referenced by real imports, which mypy and the floors test see
(a part imported only when used is imported inside a small function)."""

from __future__ import annotations

import ast
import re

from import_reader import SRC

MODULE_FUNCTION = re.compile(r"armkit(\.\w+)+:\w+")


def by_string(source: str) -> list[tuple[int, str]]:
    """(line, what) of every import by string in ``source``."""
    found = []
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, ast.Call):
            name = ast.unparse(node.func)
            if name.endswith("import_module") or name.endswith("__import__"):
                found.append((node.lineno, name))
        elif isinstance(node, ast.Constant) and isinstance(node.value, str):
            found += (
                [(node.lineno, repr(node.value))] if MODULE_FUNCTION.fullmatch(node.value) else []
            )
    return sorted(found)


def test_the_rule_finds_each_form() -> None:
    source = (
        'import importlib\nimportlib.import_module("armkit.x")\n__import__("y")\n'
        'JOBS = {"pick": "armkit.tasks:pick"}\nfrom .tasks import pick\n'
    )
    assert by_string(source) == [
        (2, "importlib.import_module"),
        (3, "__import__"),
        (4, "'armkit.tasks:pick'"),
    ]


def test_no_module_of_armkit_is_imported_by_a_string() -> None:
    paths = sorted((SRC / "armkit").rglob("*.py"))
    assert len(paths) > 100
    found = [
        f"{path.relative_to(SRC)}:{line}: {what}"
        for path in paths
        for line, what in by_string(path.read_text(encoding="utf-8"))
    ]
    assert found == []
