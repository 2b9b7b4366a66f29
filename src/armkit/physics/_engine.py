"""MuJoCo under one simulated arm and its scene: the model built from ``mjcf_of``, its
joints following the simulated servos, the cubes' poses and the jaws' contacts read
back (SI units, the scene's frame).

The arm's joints are driven by their position actuators (``interchange``'s), made
``STIFFER`` times stiffer and with gravity compensated on the arm's bodies (a servo's
integral action holds its link against gravity): a joint at rest sits on the angle its
simulated servo has (within microradians), so a cube is put down where the servo put
the gripper. The jaws' actuator squeezes with ``GRIP_KP``: while free its target is
the simulated gripper's opening, once a cube stops the jaws it is the servo's goal,
so the jaws press the cube as a position-controlled gripper servo does.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray

from .._errors import ArmkitError
from ..model import ArmModel
from ..scene import Scene
from ._hand import Scissor, clip_hand

F64 = NDArray[np.float64]
STIFFER = 30.0  # the arm's actuators' stiffness over interchange's (its STIFF_AT / this)
GRIP_KP = 1000.0  # [N/m] the jaws' squeeze per metre of the gripper servo's error
GRIP_FORCE = 10.0  # [N] the most a jaw pushes (the gripper servo's current limit)
CONTACT_S = 0.002  # [s] contacts' time constant, 2 steps (MuJoCo's 0.02: light cubes creep)
NOSLIP = 4  # MuJoCo's no-slip solver iterations (soft friction lets a held cube creep)
PALM = 1.5  # the palm begins this many pad lengths behind the tool point (the fingers' roots)
FRICTION = 1.0  # sliding friction coefficient of the jaws' pads and the cubes


def mujoco_module() -> Any:
    """The ``mujoco`` package, or ArmkitError saying how to install it (armkit imports it
    only here, when a MuJoCo world is made)."""
    try:
        import mujoco
    except ImportError as exc:
        raise ArmkitError(
            f"--physics mujoco needs MuJoCo ({exc}): pip install 'armkit[physics]'"
        ) from None
    return mujoco


@dataclass(frozen=True)
class Indices:
    """Where the arm's and cubes' values are in MuJoCo's arrays."""

    joints: tuple[int, ...]  # qpos address of each arm joint
    joint_dofs: tuple[int, ...]  # qvel address of each arm joint
    jaw: int  # qpos address of jaw_left (-1: no gripper)
    gripper: int  # the gripper's actuator (-1: none)
    cubes: dict[str, tuple[int, int, int]]  # name -> (body, qpos address, qvel address)
    jaw_bodies: tuple[int, ...]  # jaw_left, jaw_right body ids
    tool: int  # the site "tool"


class Engine:
    """One MuJoCo model and its data for ``model`` on ``scene`` (every cube, held ones too).

    Args:
        model: the arm.  scene: the table and objects, cubes where they are.
        dt: the time step [s] (the World's).  friction: the pads' and cubes' coefficient.
        edit: called with the model's ``mujoco.MjSpec`` before it is compiled.
    """

    def __init__(
        self,
        model: ArmModel,
        scene: Scene,
        dt: float,
        friction: float = FRICTION,
        edit: Callable[[Any], None] | None = None,
    ) -> None:
        from ..interchange import mjcf_of

        self.mj = mujoco_module()
        self.model, self.scene = model, scene
        spec = self.mj.MjSpec.from_string(mjcf_of(model, scene))
        if edit is not None:
            edit(spec)  # bodies the MJCF does not write (a held pen)
        self.m = spec.compile()
        self.m.opt.timestep = dt
        self.d = self.mj.MjData(self.m)
        self.mj.mj_resetDataKeyframe(self.m, self.d, 0)
        self.at = _indices(self.mj, self.m, model, scene)
        self._tune(friction)
        self.scissor: Scissor | None = None
        if model.gripper.present:
            clip_hand(self.mj, self.m, PALM * model.gripper.finger_length)
            self.scissor = Scissor.of(self.mj, self.m, model)
        self._unstick()
        self.travel = (model.gripper.width_max - model.gripper.width_min) / 2.0

    def _tune(self, friction: float) -> None:
        m, at = self.m, self.at
        for k in range(self.model.dof):  # actuators 0..dof-1 are the joints', in order
            m.actuator_gainprm[k, 0] *= STIFFER
            m.actuator_biasprm[k, 1] *= STIFFER
            m.dof_damping[at.joint_dofs[k]] *= math.sqrt(STIFFER)
        arm_bodies = [b for b in range(1, m.nbody) if not self._is_cube(b)]
        m.body_gravcomp[arm_bodies] = 1.0
        m.geom_friction[:, 0] = friction
        m.geom_solref[:, 0] = CONTACT_S  # stiff contacts: an 11 g cube is not a sponge
        m.geom_condim[:] = 4  # with torsional friction: a squeezed cube does not pivot
        m.opt.cone = self.mj.mjtCone.mjCONE_ELLIPTIC  # MuJoCo's advice for grasping:
        m.opt.impratio = 10.0  # elliptic cones, friction 10x stiffer than the normal force
        m.opt.noslip_iterations = NOSLIP  # and no creep: a held cube stays where it is held
        if at.gripper >= 0:
            m.actuator_gainprm[at.gripper, 0] = GRIP_KP
            m.actuator_biasprm[at.gripper, 1] = -GRIP_KP
            m.actuator_forcelimited[at.gripper] = 1
            m.actuator_forcerange[at.gripper] = (-GRIP_FORCE, GRIP_FORCE)
            jaw_dof = m.jnt_dofadr[m.joint("jaw_left").id]
            m.dof_damping[jaw_dof] = 2.0 * math.sqrt(GRIP_KP * float(m.body_mass[at.jaw_bodies[0]]))
            m.eq_solref[:, 0] = 2.0 * m.opt.timestep  # the jaws move as one (the mimic joint)

    def _unstick(self) -> None:
        """The arm's geoms that are already in the table or an object at home (the base
        column stands in the table: its clearance capsule reaches below the surface)
        touch nothing; else their friction would hold the waist."""
        m, d = self.m, self.d
        self.mj.mj_forward(m, d)
        for k in range(d.ncon):
            if d.contact.dist[k] > -1e-4:
                continue
            for g in d.contact.geom[k]:
                body = int(m.geom_bodyid[g])
                if body != 0 and not self._is_cube(body):
                    m.geom_contype[g] = m.geom_conaffinity[g] = 0

    def _is_cube(self, body: int) -> bool:
        return any(b == body for b, _, _ in self.at.cubes.values())

    def place(self, q: F64, opening: float, cubes: dict[str, F64]) -> None:
        """Put the arm at ``q`` [rad], the jaws at ``opening`` [m] and each named cube at
        its centre pose (4, 4) [m], at rest (before the first step)."""
        d, at = self.d, self.at
        d.qpos[list(at.joints)] = q
        d.ctrl[: self.model.dof] = q
        if at.jaw >= 0:
            d.qpos[at.jaw] = d.qpos[at.jaw + 1] = self._jaw(opening)
            d.ctrl[at.gripper] = self._jaw(opening)
        for name, T in cubes.items():
            _, adr, _ = at.cubes[name]
            d.qpos[adr : adr + 3] = T[:3, 3]
            quat = np.zeros(4)
            self.mj.mju_mat2Quat(quat, np.ascontiguousarray(T[:3, :3]).ravel())
            d.qpos[adr + 3 : adr + 7] = quat
        d.qvel[:] = 0.0
        self.mj.mj_forward(self.m, self.d)

    def _jaw(self, opening: float) -> float:
        return min(max((opening - self.model.gripper.width_min) / 2.0, 0.0), self.travel)

    def step(self, q: F64, jaws: float | None) -> None:
        """One time step with the arm's actuators at ``q`` [rad] and the jaws' at the
        opening ``jaws`` [m] (None: no gripper)."""
        d = self.d
        d.ctrl[: self.model.dof] = q
        if jaws is not None and self.at.gripper >= 0:
            d.ctrl[self.at.gripper] = self._jaw(jaws)
            if self.scissor is not None:
                self.scissor.follow(self.m, self.opening())
        self.mj.mj_step(self.m, d)

    def opening(self) -> float:
        """The jaws' opening in MuJoCo [m]."""
        if self.at.jaw < 0:
            return 0.0
        jaw, g = self.at.jaw, self.model.gripper
        return min(
            max(g.width_min + float(self.d.qpos[jaw] + self.d.qpos[jaw + 1]), g.width_min),
            g.width_max,
        )

    def cube_pose(self, name: str) -> F64:
        """The cube's centre pose in the scene frame, shape (4, 4) [m]."""
        body = self.at.cubes[name][0]
        T = np.eye(4)
        T[:3, :3] = self.d.xmat[body].reshape(3, 3)
        T[:3, 3] = self.d.xpos[body]
        return T

    def tool_pose(self) -> F64:
        """The tool site's pose in MuJoCo now (where the arm really is), shape (4, 4) [m]."""
        site = self.at.tool
        T = np.eye(4)
        T[:3, :3] = self.d.site_xmat[site].reshape(3, 3)
        T[:3, 3] = self.d.site_xpos[site]
        return T

    def cube_speed(self, name: str) -> float:
        """How fast the cube moves: its linear speed [m/s] plus its turning [rad/s] x 0.01 m."""
        _, _, dof = self.at.cubes[name]
        v = self.d.qvel[dof : dof + 6]
        return float(np.linalg.norm(v[:3]) + 0.01 * np.linalg.norm(v[3:]))

    def arm_speed(self) -> float:
        """The fastest arm joint's or jaw's speed [rad/s or m/s]."""
        return float(np.max(np.abs(self.d.qvel[: self._arm_dofs()]), initial=0.0))

    def _arm_dofs(self) -> int:
        return self.model.dof + (2 if self.at.jaw >= 0 else 0)

    def touching(self) -> tuple[set[str], set[str]]:
        """The cubes each jaw (left, right) touches now."""
        m, d, at = self.m, self.d, self.at
        if d.ncon == 0 or at.jaw < 0:
            return set(), set()
        bodies = m.geom_bodyid[d.contact.geom[: d.ncon]]  # (ncon, 2)
        names = {b: n for n, (b, _, _) in at.cubes.items()}
        out: tuple[set[str], set[str]] = (set(), set())
        for a, b in bodies:
            for side, jaw in enumerate(at.jaw_bodies):
                other = b if a == jaw else a if b == jaw else -1
                if other in names:
                    out[side].add(names[other])
        return out

    def jaw_force(self) -> float:
        """The force the gripper's actuator pushes its jaws with now [N] (0 without one)."""
        return 0.0 if self.at.gripper < 0 else abs(float(self.d.actuator_force[self.at.gripper]))


def _indices(mj: Any, m: Any, model: ArmModel, scene: Scene) -> Indices:
    joints = tuple(int(m.joint(n).qposadr[0]) for n in model.joint_names)
    dofs = tuple(int(m.joint(n).dofadr[0]) for n in model.joint_names)
    has_jaws = model.gripper.present
    jaw = int(m.joint("jaw_left").qposadr[0]) if has_jaws else -1
    gripper = int(m.actuator("gripper").id) if has_jaws else -1
    cubes = {
        c.name: (
            int(m.body(c.name).id),
            int(m.joint(c.name).qposadr[0]),
            int(m.joint(c.name).dofadr[0]),
        )
        for c in scene.cubes
    }
    jaws = (int(m.body("jaw_left").id), int(m.body("jaw_right").id)) if has_jaws else ()
    return Indices(joints, dofs, jaw, gripper, cubes, jaws, int(m.site("tool").id))
