"""No package imports another package's private module (read from the code's own
imports: every import statement, those inside functions and under TYPE_CHECKING
included).

A package's ``_module.py`` files are its own; what another package needs is
re-exported by the package's ``__init__`` (or a public module of it, e.g.
``armkit.sim.assembly``) and imported from there. The top-level private helpers
(``armkit._errors``, ``_inputs``, ``_clock``, ``_files``, ``_lock``, ``_terminal``) are the
shared floor of every package and may be imported anywhere.
"""

from __future__ import annotations

from pathlib import Path

from import_reader import SRC, imported, module_name


def _owner(module: str) -> str:
    """The package (or top-level module) of armkit a module belongs to."""
    parts = module.split(".")
    return parts[1] if len(parts) > 1 else ""


def cross_package_private(module: str, target: str) -> bool:
    """Whether ``module`` importing ``target`` reaches into another package's private part."""
    parts = target.split(".")
    if parts[0] != "armkit" or len(parts) < 3 or parts[1] == _owner(module):
        return False
    return any(part.startswith("_") for part in parts[2:])


def _violations(path: Path, source: str) -> list[str]:
    """``file:line: module`` of each import statement in ``source`` reaching into another
    package's private module (the shortest such name the statement imports)."""
    module = module_name(path)
    worst: dict[int, str] = {}
    for line, target in imported(path, source):
        if cross_package_private(module, target) and len(target) < len(
            worst.get(line, target + "_")
        ):
            worst[line] = target
    return [f"{path.relative_to(SRC)}:{line}: {target}" for line, target in sorted(worst.items())]


def test_the_rule_reads_relative_nested_and_function_level_imports() -> None:
    here = SRC / "armkit" / "drivers" / "servo" / "_x.py"
    source = (
        "from ...model._limits import limits\n"
        "from ...devices import _xm430 as xm\n"
        "from .._driver import Driver\n"  # its own package: fine
        "from ..._errors import ArmkitError\n"  # the shared floor: fine
        "from ...model import limits\n"  # the public face: fine
        "def f():\n"
        "    import armkit.sim._wire\n"
    )
    assert _violations(here, source) == [
        "armkit/drivers/servo/_x.py:1: armkit.model._limits",
        "armkit/drivers/servo/_x.py:2: armkit.devices._xm430",
        "armkit/drivers/servo/_x.py:7: armkit.sim._wire",
    ]
    top = SRC / "armkit" / "arm.py"
    assert _violations(top, "from .drivers._driver import Driver\n") == [
        "armkit/arm.py:1: armkit.drivers._driver"
    ]


def test_no_package_imports_a_private_module_of_another() -> None:
    paths = sorted((SRC / "armkit").rglob("*.py"))
    assert len(paths) > 100
    found = [v for p in paths for v in _violations(p, p.read_text(encoding="utf-8"))]
    assert found == [], "import these from the package (re-export them there):\n" + "\n".join(found)
