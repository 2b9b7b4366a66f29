"""Pictures and views of arms: the primitive shapes every view draws, the arm and
the scene as primitives, what a view follows (a ``StateSource``: the simulation
World, a driver, or another process's arm through the live channel), the target
check, GIFs of jobs.

Nothing here imports matplotlib or viser until a picture or the web view
(``armkit.viz.web``) is asked for.

Each public name is loaded from its module on first use (PEP 562), so importing
one part of the package (``armkit.viz.live`` for a kept simulated arm) loads no other."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from .._errors import NoSuchName

if TYPE_CHECKING:  # what the names below are, for type checkers (loaded on first use)
    from .._primitives import RGB as RGB
    from .._primitives import Axes as Axes
    from .._primitives import Box as Box
    from .._primitives import Capsule as Capsule
    from .._primitives import Cylinder as Cylinder
    from .._primitives import Label as Label
    from .._primitives import Polyline as Polyline
    from .._primitives import Primitive as Primitive
    from .._primitives import Sphere as Sphere
    from .._primitives import moved as moved
    from .._primitives import pose as pose
    from ..scene import cube_colour as cube_colour
    from ..scene import cube_primitive as cube_primitive
    from ._address import Address as Address
    from ._address import serve_address as serve_address
    from ._arm_shapes import arm_primitives as arm_primitives
    from ._arm_shapes import reach_of as reach_of
    from ._arm_shapes import table_primitive as table_primitive
    from ._gif import GifRecorder as GifRecorder
    from ._gif import default_tour as default_tour
    from ._gif import record_path as record_path
    from ._gif import write_gif as write_gif
    from ._gif import write_picture as write_picture
    from ._live import LivePublisher as LivePublisher
    from ._live import LiveSource as LiveSource
    from ._live import publisher_of as publisher_of
    from ._mover import Goal as Goal
    from ._mover import Mover as Mover
    from ._pose import plot_pose as plot_pose
    from ._scene_shapes import scene_primitives as scene_primitives
    from ._state import ArmSource as ArmSource
    from ._state import ObjectPose as ObjectPose
    from ._state import Snapshot as Snapshot
    from ._state import StateSource as StateSource
    from ._state import WorldSource as WorldSource
    from ._state import cubes as cubes
    from ._target import TargetCheck as TargetCheck
    from ._target import check_target as check_target
    from ._target import describe_target as describe_target


def _primitives_module() -> Any:
    from .. import _primitives as module

    return module


def _scene_module() -> Any:
    from .. import scene as module

    return module


def _address_module() -> Any:
    from . import _address as module

    return module


def _arm_shapes_module() -> Any:
    from . import _arm_shapes as module

    return module


def _gif_module() -> Any:
    from . import _gif as module

    return module


def _live_module() -> Any:
    from . import _live as module

    return module


def _mover_module() -> Any:
    from . import _mover as module

    return module


def _pose_module() -> Any:
    from . import _pose as module

    return module


def _scene_shapes_module() -> Any:
    from . import _scene_shapes as module

    return module


def _state_module() -> Any:
    from . import _state as module

    return module


def _target_module() -> Any:
    from . import _target as module

    return module


# Each public name and the module holding it, imported on first use.
_LAZY = {
    "RGB": _primitives_module,
    "Axes": _primitives_module,
    "Box": _primitives_module,
    "Capsule": _primitives_module,
    "Cylinder": _primitives_module,
    "Label": _primitives_module,
    "Polyline": _primitives_module,
    "Primitive": _primitives_module,
    "Sphere": _primitives_module,
    "moved": _primitives_module,
    "pose": _primitives_module,
    "cube_colour": _scene_module,
    "cube_primitive": _scene_module,
    "Address": _address_module,
    "serve_address": _address_module,
    "arm_primitives": _arm_shapes_module,
    "reach_of": _arm_shapes_module,
    "table_primitive": _arm_shapes_module,
    "GifRecorder": _gif_module,
    "default_tour": _gif_module,
    "record_path": _gif_module,
    "write_gif": _gif_module,
    "write_picture": _gif_module,
    "LivePublisher": _live_module,
    "LiveSource": _live_module,
    "publisher_of": _live_module,
    "Goal": _mover_module,
    "Mover": _mover_module,
    "plot_pose": _pose_module,
    "scene_primitives": _scene_shapes_module,
    "ArmSource": _state_module,
    "ObjectPose": _state_module,
    "Snapshot": _state_module,
    "StateSource": _state_module,
    "WorldSource": _state_module,
    "cubes": _state_module,
    "TargetCheck": _target_module,
    "check_target": _target_module,
    "describe_target": _target_module,
}


def __getattr__(name: str) -> Any:
    """A public name, loaded from its module the first time it is asked for."""
    module = _LAZY.get(name)
    if module is None:
        raise NoSuchName(f"module 'armkit.viz' has no attribute {name!r}")
    value = getattr(module(), name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(_LAZY))
