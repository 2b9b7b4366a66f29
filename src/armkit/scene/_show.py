"""The scene as text: one line per object, in millimetres and degrees, each object's
own (``SceneObject.listed``), under its heading in the order ``Scene.objects()`` gives."""

from __future__ import annotations

import math

from .._inputs import deg_text, mm
from ._scene import Scene


def describe(scene: Scene) -> list[str]:
    """Lines describing every object of ``scene``."""
    base = scene.T_world_base
    yaw = math.atan2(base[1, 0], base[0, 0])
    out = [
        f"scene {scene.name}" + (f" ({scene.source})" if scene.source else ""),
        f"  table at z = {scene.table_z * 1000:.1f} mm; arm base at {mm(base[:3, 3])}, "
        f"yaw {deg_text(yaw)}",
    ]
    sections: dict[str, list[str]] = {}
    for obj in scene.objects():
        heading, line = obj.listed(scene)
        sections.setdefault(heading, []).append(line)
    for heading, lines in sections.items():
        out.append(f"{heading}:")
        out.extend(f"  {line}" for line in lines)
    if len(out) == 2:
        out.append("  nothing on the table")
    return out
