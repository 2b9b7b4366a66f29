"""Arm models as data: joints, DH chain, tool and gripper, loaded from TOML."""

from ._limits import MAX_MOVE_S as MAX_MOVE_S
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
from ._sections import DynamixelSection as DynamixelSection
from ._sections import dynamixel_section as dynamixel_section
from ._types import ArmModel as ArmModel
from ._types import DHRow as DHRow
from ._types import Gripper as Gripper
from ._types import Joint as Joint
from ._types import JointFrame as JointFrame
