"""armkit: drive cheap robot arms by where the gripper should go.

The core is SI (metres, radians); ``Arm`` and the CLI speak millimetres and degrees.
"""

from ._errors import ArmkitError as ArmkitError
from ._errors import ArmkitWarning as ArmkitWarning
from ._errors import DeviceError as DeviceError
from ._errors import InputError as InputError
from ._errors import JointLimitError as JointLimitError
from ._errors import ModelError as ModelError
from ._errors import NoSolutionError as NoSolutionError
from ._errors import Reason as Reason
from ._errors import ScriptError as ScriptError
from ._errors import UnreachableError as UnreachableError
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

__version__ = "0.1.0"
