"""The floors of the house, read from the code's own imports (every import statement,
those inside functions and under TYPE_CHECKING included).

Every module stands on one floor of ``FLOORS`` and imports nothing on a floor above
its own; no modules import each other in a circle.

drivers never import sim; sim never imports drivers, motion, Arm, the factory, the CLI
or the packages above (tasks, script, viz, music, drawing); devices import neither; one
factory (``armkit.connect``) is the only place that imports both drivers and sim; the
pure floors (model, kinematics, scene, music, drawing) import nothing above, and the
packages above reach the simulator through Arm and the factory.
"""

from __future__ import annotations

from collections import defaultdict
from pathlib import Path

import pytest

from import_reader import SRC, imported, module_name

# The floors, bottom first (DESIGN.md's layers as the code has them): a module may import
# its own floor and the ones below. Side by side on one floor, the pairs of the test below
# say what may not import what.
FLOORS: tuple[tuple[str, ...], ...] = (
    ("armkit._errors", "armkit._clock", "armkit._closing", "armkit._progress",
     "armkit._terminal", "armkit._toml_files", "armkit._inputs", "armkit._files",
     "armkit._polyline", "armkit._lock", "armkit._primitives", "armkit._input_limits",
     "armkit._toml_shape", "armkit._toml_where"),  # the shared floor
    ("armkit.model",),
    ("armkit.kinematics", "armkit.devices"),
    ("armkit.drivers", "armkit.scene", "armkit.sensing", "armkit.sim", "armkit.interchange"),
    ("armkit.motion", "armkit.connect", "armkit.physics"),
    ("armkit._arm_inputs", "armkit.arm", "armkit"),  # ``armkit``: the package's face
    ("armkit.music", "armkit.tasks", "armkit.drawing"),  # the jobs
    ("armkit.script", "armkit.viz", "armkit.jobs"),  # jobs: the specs script and cli read
    ("armkit.cli",),
)  # fmt: skip


def _imports(path: Path) -> set[str]:
    """Every armkit module ``path`` imports, absolute (``from . import x`` -> ``pkg.x``)."""
    return {m for _, m in imported(path) if m == "armkit" or m.startswith("armkit.")}


# modules: the .py files, and the compiled ones by their .pyi stubs (kinematics/_numeric/_lmc)
PATHS = {
    module_name(p): p
    for p in sorted((SRC / "armkit").rglob("*.py*"))
    if p.suffix == ".py" or (p.suffix == ".pyi" and not p.with_suffix(".py").exists())
}
MODULES = {m: _imports(p) for m, p in PATHS.items()}


def _module(name: str) -> str:
    """The module an imported name is in (``armkit.arm.Arm`` -> ``armkit.arm``)."""
    while name not in PATHS:
        name = name.rpartition(".")[0]
    return name


def _edges(path: Path) -> set[str]:
    """The modules ``path`` imports: ``from pkg import module`` imports the module (not
    the package's face too, which the import reader also names)."""
    by_line: dict[int, list[str]] = defaultdict(list)
    for line, name in imported(path):
        if name == "armkit" or name.startswith("armkit."):
            by_line[line].append(name)
    out = set()
    for names in by_line.values():
        modules = {n for n in names if n in PATHS}
        for name in names:
            if any(m.startswith(name + ".") for m in modules):
                continue  # the package a module is imported from
            out.add(_module(name))
    return out - {module_name(path)}


GRAPH = {m: _edges(p) for m, p in PATHS.items()}


def _on(module: str, name: str) -> bool:
    return module == name if name == "armkit" else _in(module, name)


def _floor(module: str) -> int:
    found = [k for k, floor in enumerate(FLOORS) if any(_on(module, n) for n in floor)]
    assert found, f"{module} stands on no floor: add its package to FLOORS"
    return found[0]


def _in(module: str, floor: str) -> bool:
    return module == floor or module.startswith(floor + ".")


def _importers(floor: str, of: str) -> list[str]:
    """Modules on ``floor`` that import something on floor ``of``."""
    return sorted(
        m for m, deps in MODULES.items() if _in(m, floor) and any(_in(d, of) for d in deps)
    )


def test_the_import_reader_sees_relative_and_nested_imports() -> None:
    assert "armkit.sim._world" in MODULES["armkit.sim"]  # from ._world import ...
    assert "armkit.drivers.servo" in MODULES["armkit.connect._simulate"]
    assert len(MODULES) > 100


@pytest.mark.parametrize(
    "floor, forbidden",
    [
        ("armkit.drivers", "armkit.sim"),
        ("armkit.drivers", "armkit.connect"),
        ("armkit.devices", "armkit.sim"),
        ("armkit.devices", "armkit.drivers"),
        ("armkit.sim", "armkit.drivers"),
        ("armkit.sim", "armkit.motion"),
        ("armkit.sim", "armkit.arm"),
        ("armkit.sim", "armkit.connect"),
        ("armkit.sim", "armkit.cli"),
        ("armkit.model", "armkit.kinematics"),
        ("armkit.model", "armkit.sim"),
        ("armkit.model", "armkit.drivers"),
        ("armkit.kinematics", "armkit.motion"),
        ("armkit.kinematics", "armkit.drivers"),
        ("armkit.kinematics", "armkit.sim"),
        ("armkit.motion", "armkit.sim"),
        # the packages above the stack reach the simulator through Arm and the factory
        ("armkit.sim", "armkit.tasks"),
        ("armkit.sim", "armkit.script"),
        ("armkit.sim", "armkit.viz"),
        ("armkit.sim", "armkit.music"),
        ("armkit.sim", "armkit.drawing"),
        ("armkit.scene", "armkit.sim"),  # ScenePhysics is a World observer by protocol
        ("armkit.scene", "armkit.drivers"),
        ("armkit.scene", "armkit.arm"),
        ("armkit.scene", "armkit.tasks"),
        ("armkit.tasks", "armkit.sim"),
        ("armkit.script", "armkit.sim"),
        ("armkit.viz", "armkit.sim"),
        ("armkit.music", "armkit.sim"),
        ("armkit.music", "armkit.drivers"),
        ("armkit.drawing", "armkit.sim"),
        ("armkit.drawing", "armkit.drivers"),
        # interchange (URDF, MJCF) writes model, kinematics and scene as files: pure
        ("armkit.interchange", "armkit.sim"),
        ("armkit.interchange", "armkit.drivers"),
        ("armkit.interchange", "armkit.connect"),
        ("armkit.interchange", "armkit.arm"),
        ("armkit.interchange", "armkit.cli"),
        ("armkit.model", "armkit.interchange"),
        ("armkit.kinematics", "armkit.interchange"),
        ("armkit.scene", "armkit.interchange"),
        # MuJoCo's physics is a World observer by protocol, as ScenePhysics, over the MJCF
        ("armkit.physics", "armkit.sim"),
        ("armkit.physics", "armkit.drivers"),
        ("armkit.physics", "armkit.connect"),
        ("armkit.scene", "armkit.physics"),
        ("armkit.sim", "armkit.physics"),
        ("armkit.sensing", "armkit.sim"),  # the simulated sensor lives in sim
        ("armkit.sensing", "armkit.drivers"),
    ],
)
def test_a_floor_does_not_import_what_stands_above_or_beside_it(floor: str, forbidden: str) -> None:
    assert _importers(floor, forbidden) == []


def test_only_the_factory_imports_both_drivers_and_sim() -> None:
    both = [
        m
        for m, deps in MODULES.items()
        if any(_in(d, "armkit.drivers") for d in deps) and any(_in(d, "armkit.sim") for d in deps)
    ]
    assert both and all(_in(m, "armkit.connect") for m in both), both


def test_wire_codecs_live_in_devices() -> None:
    codecs = ("armkit.devices._owi_commands", "armkit.devices._dxl_packet")
    assert all(codec in MODULES for codec in codecs)
    assert "armkit.drivers.timed._commands" not in MODULES
    users = [m for m, deps in MODULES.items() if any(d in codecs for d in deps)]
    floors = ("armkit.devices", "armkit.drivers", "armkit.sim")  # at or above devices
    assert all(any(_in(m, f) for f in floors) for m in users), users


def test_no_module_imports_a_floor_above_its_own() -> None:
    up = sorted(
        f"{m} (floor {_floor(m)}) imports {d} (floor {_floor(d)})"
        for m, deps in GRAPH.items()
        for d in deps
        if _floor(d) > _floor(m)
    )
    assert up == []


def _circles(graph: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected groups of more than one module (Tarjan's algorithm)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    found: list[list[str]] = []

    def visit(v: str) -> None:
        index[v] = low[v] = len(index)
        stack.append(v)
        for w in graph.get(v, ()):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            group = stack[stack.index(v) :]
            del stack[stack.index(v) :]
            if len(group) > 1:
                found.append(sorted(group))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return found


def test_the_circle_finder_finds_a_circle() -> None:
    assert _circles({"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}) == [["a", "b", "c"]]
    assert _circles({"a": {"b"}, "b": set()}) == []


def test_no_modules_import_each_other_in_a_circle() -> None:
    assert _circles(GRAPH) == []
