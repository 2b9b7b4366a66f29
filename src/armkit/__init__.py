"""armkit: drive cheap robot arms by where the gripper should go.

The core is SI (metres, radians); ``Arm`` and the CLI speak millimetres and degrees.
"""

from typing import TYPE_CHECKING, Any

from ._errors import ArmkitError as ArmkitError
from ._errors import ArmkitWarning as ArmkitWarning
from ._errors import DeviceError as DeviceError
from ._errors import InputError as InputError
from ._errors import JointLimitError as JointLimitError
from ._errors import ModelError as ModelError
from ._errors import NoSolutionError as NoSolutionError
from ._errors import NoSuchName as NoSuchName
from ._errors import Reason as Reason
from ._errors import ScriptError as ScriptError
from ._errors import UnreachableError as UnreachableError

if TYPE_CHECKING:  # what the names below are, for type checkers (loaded on first use)
    from .arm import Arm as Arm
    from .arm import Position as Position
    from .kinematics import IKBatchResult as IKBatchResult
    from .kinematics import IKResult as IKResult
    from .kinematics import Target as Target
    from .kinematics import fk as fk
    from .kinematics import fk_frames as fk_frames
    from .kinematics import ik as ik
    from .kinematics import ik_batch as ik_batch
    from .kinematics import jacobian as jacobian
    from .kinematics import pitch_of as pitch_of
    from .model import ArmModel as ArmModel
    from .model import load_model as load_model


def _arm() -> Any:
    from . import arm

    return arm


def _kinematics() -> Any:
    from . import kinematics

    return kinematics


def _model() -> Any:
    from . import model

    return model


# Each public name and the package holding it, imported on first use (PEP 562), so
# ``import armkit`` costs only what the names a program uses need.
_LAZY = {
    "Arm": _arm,
    "Position": _arm,
    "IKBatchResult": _kinematics,
    "IKResult": _kinematics,
    "Target": _kinematics,
    "fk": _kinematics,
    "fk_frames": _kinematics,
    "ik": _kinematics,
    "ik_batch": _kinematics,
    "jacobian": _kinematics,
    "pitch_of": _kinematics,
    "ArmModel": _model,
    "load_model": _model,
}


def __getattr__(name: str) -> Any:
    """A public name, loaded from its package the first time it is asked for."""
    package = _LAZY.get(name)
    if package is None:
        raise NoSuchName(
            f"module 'armkit' has no attribute {name!r}; its names: {', '.join(sorted(_LAZY))}"
        )
    value = getattr(package(), name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(_LAZY))


__version__ = "0.1.0"
