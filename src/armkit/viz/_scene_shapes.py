"""A scene (``armkit.scene.Scene``) as primitives: every object as it draws itself
(``SceneObject.primitives``).

Everything is in the scene's (table's) frame [m]; the arm is drawn there through
``Scene.T_world_base``. Names are stable (``/scene/<object name>``,
``/scene/<board>_sockets/<row>_<col>``), so a view moves a cube by redrawing
the primitive of the same name (``armkit.scene.cube_primitive``).
"""

from __future__ import annotations

from .._primitives import Primitive
from ..scene import Scene


def scene_primitives(scene: Scene) -> list[Primitive]:
    """Every object of ``scene`` (the table is the view's own ``table_primitive``)."""
    return [shape for obj in scene.objects() for shape in obj.primitives(scene)]
