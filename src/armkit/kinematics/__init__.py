"""Pure kinematics on an ArmModel: FK, frames, Jacobian, closed-form and numeric IK (SI units)."""

from ._chain import joint_frames as joint_frames
from ._forward import fk as fk
from ._forward import fk_frames as fk_frames
from ._forward import frames_on_base_axis as frames_on_base_axis
from ._forward import jacobian as jacobian
from ._ik import MethodName as MethodName
from ._ik import closed_form as closed_form
from ._ik import ik as ik
from ._ik import ik_batch as ik_batch
from ._ik import pitch_follows as pitch_follows
from ._ik import why_no_closed_form as why_no_closed_form
from ._pose import pitch_of as pitch_of
from ._result import IKBatchResult as IKBatchResult
from ._result import IKResult as IKResult
from ._result import Method as Method
from ._target import Target as Target
