"""One name per idea (issue 26 item 6): a class or function name that armkit's public
modules show names one thing. Each public module (no part of its path private) is read
for the classes and functions it offers (``__all__``, its lazy ``_LAZY`` table, else its
public globals); a name bound to two different objects is a collision."""

from __future__ import annotations

import ast
import importlib
import inspect
import pkgutil
from collections import defaultdict

import armkit

# Collisions known and left, each with why (delete an entry once it is gone):
KNOWN = {
    # a figure on a sheet (drawing.shapes: exact paths in u, v) and a sampled path in
    # space (motion: points at a spacing) are two ideas of one word each
    "arc", "circle", "line", "polyline", "rectangle",
}  # fmt: skip


def _public_modules() -> list[str]:
    names = ["armkit"]
    for info in pkgutil.walk_packages(armkit.__path__, "armkit."):
        if not any(part.startswith("_") for part in info.name.split(".")[1:]):
            names.append(info.name)
    return names


def _offered(module: object) -> list[str]:
    """What ``module`` offers: its ``__all__`` and lazy names, the public names it defines,
    and those it re-exports (``from ._x import y as y``, PEP 484's explicit re-export;
    a plain import is a module's own use, not its face)."""
    name = getattr(module, "__name__", "")
    names = [*(getattr(module, "__all__", None) or []), *getattr(module, "_LAZY", {})]
    names += [
        attr
        for attr, value in vars(module).items()
        if not attr.startswith("_") and getattr(value, "__module__", "") == name
    ]
    try:
        tree = ast.parse(inspect.getsource(module))  # type: ignore[arg-type]
    except (OSError, TypeError):
        return names
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom):
            names += [alias.name for alias in node.names if alias.asname == alias.name]
    return names


def collisions() -> dict[str, set[str]]:
    """Name -> the objects (module.qualname) it is bound to, where more than one."""
    seen: dict[str, set[str]] = defaultdict(set)
    for name in _public_modules():
        try:
            module = importlib.import_module(name)
        except ImportError:  # an extra that is not installed
            continue
        for attr in _offered(module):
            value = getattr(module, attr, None)
            ours = inspect.isclass(value) or inspect.isfunction(value)
            if ours and value.__module__.startswith("armkit"):
                seen[attr].add(f"{value.__module__}.{value.__qualname__}")
    return {name: found for name, found in seen.items() if len(found) > 1}


def test_every_public_name_names_one_thing() -> None:
    found = collisions()
    assert {name: found[name] for name in set(found) - KNOWN} == {}
    assert set(KNOWN) - set(found) == set(), "gone: delete them from KNOWN"
