"""The kinematics package's shape: no import circle (function-level imports included),
no mutable cache on the model, and no module reaching into a sibling's private helpers
through a circle."""

from __future__ import annotations

from pathlib import Path

import armkit.kinematics
from import_reader import imported, module_name

ROOT = Path(armkit.kinematics.__file__).parent
PACKAGE = "armkit.kinematics"


def _is_package(name: str) -> bool:
    return (ROOT / Path(*name.split(".")[2:]) / "__init__.py").exists()


def _imports(path: Path, source: str | None = None) -> set[str]:
    """Every kinematics module ``path`` imports, anywhere in the file (functions included)."""
    me = module_name(path)
    found = {
        t
        for _, t in imported(path, source)
        if t.startswith(PACKAGE)
        and ((ROOT / Path(*t.split(".")[2:])).with_suffix(".py").exists() or _is_package(t))
    }
    ancestors = {".".join(me.split(".")[:k]) for k in range(2, len(me.split(".")) + 1)}
    return found - ancestors  # a package is initialised before its modules run


def _graph() -> dict[str, set[str]]:
    return {module_name(p): _imports(p) for p in ROOT.rglob("*.py")}


def _cycle(graph: dict[str, set[str]]) -> list[str] | None:
    state: dict[str, int] = {}
    stack: list[str] = []

    def visit(node: str) -> list[str] | None:
        state[node] = 1
        stack.append(node)
        for nxt in sorted(graph.get(node, ())):
            if state.get(nxt) == 1:
                return [*stack[stack.index(nxt) :], nxt]
            if nxt not in state and (found := visit(nxt)):
                return found
        stack.pop()
        state[node] = 2
        return None

    for node in sorted(graph):
        if node not in state and (found := visit(node)):
            return found
    return None


def test_the_reader_sees_imports_inside_functions() -> None:
    source = "def f():\n    from ._chain import chain_of\n    from .._errors import InputError\n"
    assert _imports(ROOT / "_result.py", source) == {f"{PACKAGE}._chain"}
    assert _cycle({"a": {"b"}, "b": {"a"}}) == ["a", "b", "a"]
    assert _imports(ROOT / "_ik.py") >= {f"{PACKAGE}._chain", f"{PACKAGE}._numeric"}


def test_no_import_circle_in_kinematics() -> None:
    graph = _graph()
    assert len(graph) > 20
    assert _cycle(graph) is None


def test_no_cache_on_the_model() -> None:
    src = ROOT.parent
    offenders = [p for p in src.rglob("*.py") if "_cache" in p.read_text()]
    assert offenders == []
