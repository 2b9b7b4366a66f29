"""Pure kinematics on an ArmModel: FK, frames, Jacobian, closed-form IK (SI units)."""

from ._fk import fk as fk
from ._fk import fk_frames as fk_frames
from ._ik import ik as ik
from ._ik import ik_batch as ik_batch
from ._jacobian import jacobian as jacobian
from ._pose import pitch_of as pitch_of
from ._result import IKBatchResult as IKBatchResult
from ._result import IKResult as IKResult
from ._target import Target as Target
