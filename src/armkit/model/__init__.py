"""Arm models as data: joints, DH chain, tool and gripper, loaded from TOML.

Each public name is loaded from its module on first use (PEP 562), so importing
one light part of the package loads no other."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from .._errors import NoSuchName

if TYPE_CHECKING:  # what the names below are, for type checkers (loaded on first use)
    from ._check import MAX_MOVE_S as MAX_MOVE_S
    from ._feetech_section import FeetechSection as FeetechSection
    from ._limits import check_duration as check_duration
    from ._limits import check_grip as check_grip
    from ._limits import check_joints as check_joints
    from ._limits import check_speed as check_speed
    from ._limits import limits as limits
    from ._limits import move_time as move_time
    from ._limits import ramp_time as ramp_time
    from ._limits import shortest_time as shortest_time
    from ._limits import trapezoid_time as trapezoid_time
    from ._load import load_model as load_model
    from ._load import shipped_models as shipped_models
    from ._owi_section import OwiSection as OwiSection
    from ._owi_section import owi_section as owi_section
    from ._sections import DYNAMIXEL_SECTION as DYNAMIXEL_SECTION
    from ._sections import FEETECH_SECTION as FEETECH_SECTION
    from ._sections import MAESTRO_SECTION as MAESTRO_SECTION
    from ._sections import OWI535_SECTION as OWI535_SECTION
    from ._sections import SECTIONS as SECTIONS
    from ._sections import SSC32_SECTION as SSC32_SECTION
    from ._sections import DynamixelSection as DynamixelSection
    from ._sections import Section as Section
    from ._sections import ServoSection as ServoSection
    from ._sections import dynamixel_section as dynamixel_section
    from ._sections import servo_section as servo_section
    from ._types import ArmModel as ArmModel
    from ._types import DHRow as DHRow
    from ._types import Gripper as Gripper
    from ._types import Joint as Joint
    from ._types import JointFrame as JointFrame


def _check_module() -> Any:
    from . import _check as module

    return module


def _limits_module() -> Any:
    from . import _limits as module

    return module


def _load_module() -> Any:
    from . import _load as module

    return module


def _owi_section_module() -> Any:
    from . import _owi_section as module

    return module


def _feetech_section_module() -> Any:
    from . import _feetech_section as module

    return module


def _sections_module() -> Any:
    from . import _sections as module

    return module


def _types_module() -> Any:
    from . import _types as module

    return module


# Each public name and the module holding it, imported on first use.
_LAZY = {
    "MAX_MOVE_S": _check_module,
    "check_duration": _limits_module,
    "check_grip": _limits_module,
    "check_joints": _limits_module,
    "check_speed": _limits_module,
    "limits": _limits_module,
    "move_time": _limits_module,
    "ramp_time": _limits_module,
    "shortest_time": _limits_module,
    "trapezoid_time": _limits_module,
    "load_model": _load_module,
    "shipped_models": _load_module,
    "OwiSection": _owi_section_module,
    "owi_section": _owi_section_module,
    "FeetechSection": _feetech_section_module,
    "DYNAMIXEL_SECTION": _sections_module,
    "FEETECH_SECTION": _sections_module,
    "MAESTRO_SECTION": _sections_module,
    "OWI535_SECTION": _sections_module,
    "SECTIONS": _sections_module,
    "SSC32_SECTION": _sections_module,
    "DynamixelSection": _sections_module,
    "Section": _sections_module,
    "dynamixel_section": _sections_module,
    "ServoSection": _sections_module,
    "servo_section": _sections_module,
    "ArmModel": _types_module,
    "DHRow": _types_module,
    "Gripper": _types_module,
    "Joint": _types_module,
    "JointFrame": _types_module,
}


def __getattr__(name: str) -> Any:
    """A public name, loaded from its module the first time it is asked for."""
    module = _LAZY.get(name)
    if module is None:
        raise NoSuchName(f"module 'armkit.model' has no attribute {name!r}")
    value = getattr(module(), name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(_LAZY))
