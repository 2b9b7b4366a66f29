"""``Arm``: plan a motion from a ``Start``, carry a ``Plan`` out on a driver (mm, deg).

The planners (``plan_joints``, ``plan_follow``, ``plan_through``, ``plan_grip``) work in
SI from a ``Start`` with no arm open: ``armkit check`` and the jobs plan with them,
``Arm.run`` carries their plans out.
"""

from ..model import MAX_MOVE_S as MAX_MOVE_S
from ._arm import GRIP_S as GRIP_S
from ._arm import Arm as Arm
from ._arm import Position as Position
from ._carry import REACHED as REACHED
from ._plan import Plan as Plan
from ._plan import Step as Step
from ._plan import cube_text as cube_text
from ._plan import step_text as step_text
from ._planner import plan_follow as plan_follow
from ._planner import plan_grip as plan_grip
from ._planner import plan_joints as plan_joints
from ._planner import plan_light as plan_light
from ._planner import plan_motor_run as plan_motor_run
from ._planner import plan_steps as plan_steps
from ._planner import plan_through as plan_through
from ._planner import plan_wait as plan_wait
from ._planner import refuse as refuse
from ._start import Start as Start
