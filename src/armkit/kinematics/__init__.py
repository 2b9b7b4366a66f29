"""Pure kinematics on an ArmModel: FK, frames, Jacobian, closed-form IK (SI units)."""

from ._fk import fk as fk
from ._fk import fk_frames as fk_frames
from ._jacobian import jacobian as jacobian
from ._pose import pitch_of as pitch_of
