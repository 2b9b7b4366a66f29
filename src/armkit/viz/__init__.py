"""Pictures and views of arms: the primitive shapes every view draws, the arm as
primitives, what a view follows (``StateSource``), the target check, GIFs.

Nothing here imports matplotlib or viser until a picture or the web view
(``armkit.viz.web``) is asked for.
"""

from ._arm_shapes import Capsules as Capsules
from ._arm_shapes import arm_primitives as arm_primitives
from ._arm_shapes import link_capsules as link_capsules
from ._arm_shapes import table_primitive as table_primitive
from ._cubes import cubes_scene as cubes_scene
from ._gif import default_tour as default_tour
from ._gif import record_path as record_path
from ._gif import write_gif as write_gif
from ._mover import Goal as Goal
from ._mover import Mover as Mover
from ._pose import plot_pose as plot_pose
from ._primitives import RGB as RGB
from ._primitives import Axes as Axes
from ._primitives import Box as Box
from ._primitives import Capsule as Capsule
from ._primitives import Cylinder as Cylinder
from ._primitives import Label as Label
from ._primitives import Polyline as Polyline
from ._primitives import Primitive as Primitive
from ._primitives import Sphere as Sphere
from ._primitives import pose as pose
from ._state import ArmState as ArmState
from ._state import DriverSource as DriverSource
from ._state import ObjectPose as ObjectPose
from ._state import StateSource as StateSource
from ._target import TargetCheck as TargetCheck
from ._target import check_target as check_target
from ._target import table_clearance as table_clearance
