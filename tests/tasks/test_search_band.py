"""The search says where it can see (issue 28): it missed an object nearer than about
140 mm from the base (the sensor, held 90 mm out, sees nothing within its 4 cm
minimum) while advising "within 30 cm". Now a search that finds nothing says the band
it saw, from the base axis (the CLI: put the object there; nearer it is inside the
sensor's minimum), and the object in that band is found."""

from __future__ import annotations

from pathlib import Path

import numpy as np

import armkit.scene
from armkit import Arm, tasks
from armkit.scene import load_scene
from armkit.sim import World

SHIPPED = Path(armkit.scene.__file__).parent / "scenes" / "search_002.toml"


def _search(tmp_path: Path, distance_mm: float) -> tasks.SearchResult:
    """The Lynx6 searches for 002's object moved along its bearing to ``distance_mm`` from
    the base axis (the file has it at (170, -60) mm, 180 mm out)."""
    x, y = np.array([170.0, -60.0]) / np.hypot(170.0, -60.0) * distance_mm
    text = SHIPPED.read_text().replace("[170.0, -60.0, 0.0]", f"[{x:.3f}, {y:.3f}, 0.0]")
    path = tmp_path / "search.toml"
    path.write_text(text)
    scene = load_scene(path)
    with Arm("lynx6", "sim", world=World(), scene=scene) as arm:
        return tasks.search(arm, scene)


def test_a_search_that_sees_nothing_says_the_band_it_saw() -> None:
    scene = load_scene("search_002")
    with Arm("lynx6", "sim", world=World(), scene=scene) as arm:
        result = tasks.search(arm, scene, start=100.0, stop=120.0)
    assert not result.found
    near, far = (round(b) for b in result.band)  # mm
    assert (near, far) == (130, 390)  # held 90 mm out, the sensor's 4..30 cm beyond
    assert result.lines()[-1] == "nothing found 130..390 mm from the base axis along the arc"


def test_an_object_in_the_band_is_found(tmp_path: Path) -> None:
    result = _search(tmp_path, float(np.hypot(170.0, -60.0)))  # where the file has it
    assert result.found and result.position is not None
    near, far = result.band
    assert near < float(np.linalg.norm(result.position[:2])) < far  # mm
