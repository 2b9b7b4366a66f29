"""Real physics under the simulated arm: MuJoCo moving the scene's objects.

``MujocoPhysics`` is a World observer that steps a MuJoCo model of the arm and its
scene (``armkit.interchange.mjcf_of``) with the world's clock, the arm's joints
following the simulated servos; ``physics_for`` turns a scene's rule-based physics
into MuJoCo's when the scene says ``physics = "mujoco"`` (``--physics mujoco``).
``mujoco`` itself is imported only when a MuJoCo world is made (``pip install
'armkit[physics]'``).
"""

from ._choose import physics_for as physics_for
from ._engine import FRICTION as FRICTION
from ._engine import Engine as Engine
from ._engine import mujoco_module as mujoco_module
from ._mujoco import GripSample as GripSample
from ._mujoco import MujocoPhysics as MujocoPhysics
from ._pen import MujocoPenTracer as MujocoPenTracer

__all__ = [
    "FRICTION",
    "Engine",
    "GripSample",
    "MujocoPenTracer",
    "MujocoPhysics",
    "mujoco_module",
    "physics_for",
]
