"""The floors of the house, read from the code's own imports (every import statement,
those inside functions and under TYPE_CHECKING included).

drivers never import sim; sim never imports drivers, motion, Arm, the factory, the CLI
or the packages above (tasks, script, viz, music, drawing); devices import neither; one
factory (``armkit.connect``) is the only place that imports both drivers and sim; the
pure floors (model, kinematics, scene, music, drawing) import nothing above, and the
packages above reach the simulator through Arm and the factory.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from import_reader import SRC, imported, module_name


def _imports(path: Path) -> set[str]:
    """Every armkit module ``path`` imports, absolute (``from . import x`` -> ``pkg.x``)."""
    return {m for _, m in imported(path) if m == "armkit" or m.startswith("armkit.")}


MODULES = {module_name(p): _imports(p) for p in sorted((SRC / "armkit").rglob("*.py"))}


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
