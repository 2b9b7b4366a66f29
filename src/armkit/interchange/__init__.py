"""Interchange: an arm (and its scene) as files other robotics tools open: URDF
(RViz, yourdfpy, pybullet, MuJoCo, Pinocchio) and MuJoCo's MJCF. Pure functions of
a model and a scene returning XML text; the links are the clearance capsules with
mass properties from a density."""

from ._bodies import MIN_RADIUS as MIN_RADIUS
from ._inertia import DENSITY as DENSITY
from ._mjcf import mjcf_of as mjcf_of
from ._mjcf_scene import CUBE_DENSITY as CUBE_DENSITY
from ._urdf import urdf_of as urdf_of
