"""The building blocks of a task plan, for other job packages (``armkit.drawing``'s
pen): the planning ``Options``, the ``Context`` a plan is made in, the planned
``State`` (arm pose and what is held) and the steps that extend it (``grip``,
``down`` to a point, ``up`` to the transit height)."""

from ._state import Context as Context
from ._state import Options as Options
from ._state import State as State
from ._state import down as down
from ._state import grip as grip
from ._state import up as up
