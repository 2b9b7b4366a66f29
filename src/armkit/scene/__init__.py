"""What is on the table: boards with sockets, cubes, containers, places, pens,
sheets and instruments (pure data and geometry, SI units inside), loaded from
TOML scene files written in millimetres and degrees; and the clearance check of
the arm's links against them. Every kind of object is one module and one entry of
``OBJECT_KINDS``, and answers one protocol (``SceneObject``: its name, its solids
for the clearance check, its primitives for the views).

Each public name is loaded from its module on first use (PEP 562), so importing
one light part of the package loads no other."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from .._errors import NoSuchName

if TYPE_CHECKING:  # what the names below are, for type checkers (loaded on first use)
    from ._board import Board as Board
    from ._capsules import Capsules as Capsules
    from ._capsules import arm_capsules as arm_capsules
    from ._capsules import link_names as link_names
    from ._clearance import Collision as Collision
    from ._clearance import Held as Held
    from ._clearance import check_clear as check_clear
    from ._clearance import joint_sweep as joint_sweep
    from ._clearance import joint_sweeps as joint_sweeps
    from ._container import Container as Container
    from ._cube import DROP_HEIGHT as DROP_HEIGHT
    from ._cube import FLAT_TILT as FLAT_TILT
    from ._cube import Cube as Cube
    from ._cube import Settled as Settled
    from ._cube import cube_colour as cube_colour
    from ._cube import cube_primitive as cube_primitive
    from ._cube import settle as settle
    from ._errors import SceneError as SceneError
    from ._grasp import MIN_COVER as MIN_COVER
    from ._grasp import grasp as grasp
    from ._hand import Hand as Hand
    from ._instruments import Drum as Drum
    from ._instruments import Xylophone as Xylophone
    from ._instruments import midi_note as midi_note
    from ._instruments import note_name as note_name
    from ._instruments import note_number as note_number
    from ._kinds import OBJECT_KINDS as OBJECT_KINDS
    from ._load import load_scene as load_scene
    from ._object import ObjectKind as ObjectKind
    from ._object import Placed as Placed
    from ._object import SceneObject as SceneObject
    from ._object import Solid as Solid
    from ._object import Support as Support
    from ._object import support_under as support_under
    from ._pen import HeldTool as HeldTool
    from ._pen import Pen as Pen
    from ._pen import PenStand as PenStand
    from ._physics import EventKind as EventKind
    from ._physics import SceneEvent as SceneEvent
    from ._physics import ScenePhysics as ScenePhysics
    from ._picture import PICTURE_SUFFIXES as PICTURE_SUFFIXES
    from ._picture import top_view as top_view
    from ._place import Place as Place
    from ._rect import Rect as Rect
    from ._refusal import is_inside as is_inside
    from ._refusal import move_refusal as move_refusal
    from ._rotations import yaw_and_face as yaw_and_face
    from ._scene import PHYSICS as PHYSICS
    from ._scene import Scene as Scene
    from ._shipped import shipped_scenes as shipped_scenes
    from ._show import describe as describe
    from ._state import load_physics as load_physics
    from ._state import physics_text as physics_text
    from ._state import rest_scene as rest_scene
    from ._state import save_physics as save_physics
    from ._state import scene_state_file as scene_state_file
    from ._surfaces import PAPER_SIZES as PAPER_SIZES
    from ._surfaces import Sheet as Sheet


def _board_module() -> Any:
    from . import _board as module

    return module


def _capsules_module() -> Any:
    from . import _capsules as module

    return module


def _clearance_module() -> Any:
    from . import _clearance as module

    return module


def _container_module() -> Any:
    from . import _container as module

    return module


def _cube_module() -> Any:
    from . import _cube as module

    return module


def _errors_module() -> Any:
    from . import _errors as module

    return module


def _grasp_module() -> Any:
    from . import _grasp as module

    return module


def _hand_module() -> Any:
    from . import _hand as module

    return module


def _instruments_module() -> Any:
    from . import _instruments as module

    return module


def _kinds_module() -> Any:
    from . import _kinds as module

    return module


def _load_module() -> Any:
    from . import _load as module

    return module


def _shipped_module() -> Any:
    from . import _shipped as module

    return module


def _object_module() -> Any:
    from . import _object as module

    return module


def _pen_module() -> Any:
    from . import _pen as module

    return module


def _rotations_module() -> Any:
    from . import _rotations as module

    return module


def _physics_module() -> Any:
    from . import _physics as module

    return module


def _picture_module() -> Any:
    from . import _picture as module

    return module


def _place_module() -> Any:
    from . import _place as module

    return module


def _rect_module() -> Any:
    from . import _rect as module

    return module


def _refusal_module() -> Any:
    from . import _refusal as module

    return module


def _scene_module() -> Any:
    from . import _scene as module

    return module


def _show_module() -> Any:
    from . import _show as module

    return module


def _state_module() -> Any:
    from . import _state as module

    return module


def _surfaces_module() -> Any:
    from . import _surfaces as module

    return module


# Each public name and the module holding it, imported on first use.
_LAZY = {
    "Board": _board_module,
    "Capsules": _capsules_module,
    "arm_capsules": _capsules_module,
    "link_names": _capsules_module,
    "Collision": _clearance_module,
    "Held": _clearance_module,
    "check_clear": _clearance_module,
    "joint_sweep": _clearance_module,
    "joint_sweeps": _clearance_module,
    "Container": _container_module,
    "Cube": _cube_module,
    "Settled": _cube_module,
    "cube_colour": _cube_module,
    "cube_primitive": _cube_module,
    "settle": _cube_module,
    "DROP_HEIGHT": _cube_module,
    "FLAT_TILT": _cube_module,
    "SceneError": _errors_module,
    "MIN_COVER": _grasp_module,
    "grasp": _grasp_module,
    "Hand": _hand_module,
    "Drum": _instruments_module,
    "Xylophone": _instruments_module,
    "midi_note": _instruments_module,
    "note_name": _instruments_module,
    "note_number": _instruments_module,
    "OBJECT_KINDS": _kinds_module,
    "load_scene": _load_module,
    "shipped_scenes": _shipped_module,
    "ObjectKind": _object_module,
    "Placed": _object_module,
    "SceneObject": _object_module,
    "Solid": _object_module,
    "Support": _object_module,
    "support_under": _object_module,
    "Pen": _pen_module,
    "HeldTool": _pen_module,
    "PenStand": _pen_module,
    "SceneEvent": _physics_module,
    "EventKind": _physics_module,
    "yaw_and_face": _rotations_module,
    "ScenePhysics": _physics_module,
    "PICTURE_SUFFIXES": _picture_module,
    "top_view": _picture_module,
    "Place": _place_module,
    "Rect": _rect_module,
    "is_inside": _refusal_module,
    "move_refusal": _refusal_module,
    "Scene": _scene_module,
    "PHYSICS": _scene_module,
    "describe": _show_module,
    "load_physics": _state_module,
    "physics_text": _state_module,
    "rest_scene": _state_module,
    "save_physics": _state_module,
    "scene_state_file": _state_module,
    "PAPER_SIZES": _surfaces_module,
    "Sheet": _surfaces_module,
}


def __getattr__(name: str) -> Any:
    """A public name, loaded from its module the first time it is asked for."""
    module = _LAZY.get(name)
    if module is None:
        raise NoSuchName(f"module 'armkit.scene' has no attribute {name!r}")
    value = getattr(module(), name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(_LAZY))
