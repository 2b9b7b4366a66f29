"""Pictures and views of arms: the primitive shapes every view draws, the arm and
the scene as primitives, what a view follows (a ``StateSource``: the simulation
World, a driver, or another process's arm through the live channel), the target
check, GIFs of jobs.

Nothing here imports matplotlib or viser until a picture or the web view
(``armkit.viz.web``) is asked for.
"""

from .._primitives import RGB as RGB
from .._primitives import Axes as Axes
from .._primitives import Box as Box
from .._primitives import Capsule as Capsule
from .._primitives import Cylinder as Cylinder
from .._primitives import Label as Label
from .._primitives import Polyline as Polyline
from .._primitives import Primitive as Primitive
from .._primitives import Sphere as Sphere
from .._primitives import moved as moved
from .._primitives import pose as pose
from ..scene import cube_colour as cube_colour
from ..scene import cube_primitive as cube_primitive
from ._address import Address as Address
from ._address import serve_address as serve_address
from ._arm_shapes import arm_primitives as arm_primitives
from ._arm_shapes import reach_of as reach_of
from ._arm_shapes import table_primitive as table_primitive
from ._gif import GifRecorder as GifRecorder
from ._gif import default_tour as default_tour
from ._gif import record_path as record_path
from ._gif import write_gif as write_gif
from ._gif import write_picture as write_picture
from ._live import LivePublisher as LivePublisher
from ._live import LiveSource as LiveSource
from ._live import publisher_of as publisher_of
from ._mover import Goal as Goal
from ._mover import Mover as Mover
from ._pose import plot_pose as plot_pose
from ._scene_shapes import scene_primitives as scene_primitives
from ._state import ArmSource as ArmSource
from ._state import ObjectPose as ObjectPose
from ._state import Snapshot as Snapshot
from ._state import StateSource as StateSource
from ._state import WorldSource as WorldSource
from ._state import cubes as cubes
from ._target import TargetCheck as TargetCheck
from ._target import check_target as check_target
from ._target import describe as describe
