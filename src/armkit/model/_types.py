"""What an arm IS: joints, kinematic chain, tool and gripper (SI units inside)."""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any, Literal

import numpy as np
from numpy.typing import NDArray

from .._errors import InputError
from .._inputs import brief, is_number, shown
from ._check import MAX_LENGTH_MM, MIN_LENGTH_MM

Convention = Literal["standard", "modified", "frames"]


@dataclass(frozen=True)
class DHRow:
    """One Denavit-Hartenberg row, in the convention named by the model.

    Standard:  T = Rz(theta) Tz(d) Tx(a) Rx(alpha); the joint turns about z_{i-1}.
    Modified (Craig): T = Rx(alpha) Tx(a) Rz(theta) Tz(d); the joint turns about z_i.
    The DH angle is ``theta = sign * q + theta_offset`` where q is the model's joint angle.

    Attributes:
        a: link length [m].  alpha: link twist [rad].  d: link offset [m].
        theta_offset: added to the DH angle [rad].  sign: +1.0, or -1.0 for a flipped joint.
    """

    a: float
    alpha: float
    d: float
    theta_offset: float = 0.0
    sign: float = 1.0


@dataclass(frozen=True, eq=False)
class JointFrame:
    """One joint of a general serial chain, as URDF describes it.

    The joint's frame is ``origin`` (a fixed transform from the previous joint's
    frame, or from the world for the first joint), then a rotation by the joint
    angle q about ``axis``. DH rows are one way to fill it; a URDF file another.

    Attributes:
        origin: T_parent_joint at q = 0, shape (4, 4) [m].
        axis: the rotation axis in the joint's frame, a unit vector.
    """

    origin: NDArray[np.float64]
    axis: tuple[float, float, float]


@dataclass(frozen=True)
class Joint:
    """A revolute joint as the arm's users name and measure it.

    Attributes:
        name: the seed's name for it (``"shoulder"``).
        lower, upper: limits [rad], lower < upper.
        home: home angle [rad].
        max_velocity: [rad/s].  max_acceleration: [rad/s^2]: what moves are planned with.
        servo_velocity, servo_acceleration: the servo's own physical limits [rad/s],
            [rad/s^2] (None: the same as max_*): a move given its duration may use them
            (music's strikes), as the servo itself allows.
    """

    name: str
    lower: float
    upper: float
    home: float
    max_velocity: float = math.radians(90.0)
    max_acceleration: float = math.radians(360.0)
    servo_velocity: float | None = None
    servo_acceleration: float | None = None

    @property
    def peak_velocity(self) -> float:
        """The most the servo turns [rad/s]: ``servo_velocity``, else ``max_velocity``."""
        return self.max_velocity if self.servo_velocity is None else self.servo_velocity

    @property
    def peak_acceleration(self) -> float:
        """The most the servo accelerates [rad/s^2]: ``servo_acceleration``, else the max."""
        a = self.servo_acceleration
        return self.max_acceleration if a is None else a


@dataclass(frozen=True)
class Gripper:
    """The gripper: its kind, width range and, for scissor grippers, how the
    grip point's distance depends on the width.

    Attributes:
        kind: ``"parallel"``, ``"scissor"`` or ``"timed"`` (OWI: open or closed only).
        width_min, width_max: opening range [m].
        length_poly: grip length [m] as polynomial coefficients of width [m],
            lowest order first, used for width > 0 (empty: fixed length).
        closed_length: grip length to the tip when fully closed [m], or None.
        jaw_axis: the tool frame's axis the jaws close along, ``"y"`` or ``"z"``.
        finger_length: each jaw's pad along the approach axis, centred on the tool
            point [m].  finger_width: the pad across it (along the third axis) [m].
    """

    kind: str = "parallel"
    width_min: float = 0.0
    width_max: float = 0.0
    length_poly: tuple[float, ...] = ()
    closed_length: float | None = None
    jaw_axis: str = "z"
    finger_length: float = 0.02
    finger_width: float = 0.02

    @property
    def present(self) -> bool:
        """False for an arm without a gripper (its model gives no width range)."""
        return self.width_max > self.width_min

    def length_at(self, width: float) -> float | None:
        """Grip length [m] at an opening ``width`` [m]; None if the length is fixed."""
        if not self.length_poly:
            return None
        if width <= 0.0 and self.closed_length is not None:
            return self.closed_length
        return float(sum(c * width**k for k, c in enumerate(self.length_poly)))


@dataclass(frozen=True, eq=False)
class ArmModel:
    """A serial arm: joints in chain order, its chain (DH rows or joint frames),
    tool transform, gripper.

    Attributes:
        name: short name (``"owi535"``).
        description: one line for people.
        convention: ``"standard"`` or ``"modified"`` DH, or ``"frames"`` (no DH rows:
            the chain is ``frames``, e.g. from a URDF file).
        joints: the joints, base first.
        dh: one DH row per joint (empty for ``"frames"``).
        T_flange_tool: last DH frame (or last joint frame) to tool frame, shape (4, 4) [m]; the tool
            frame's x axis is the approach direction (where the gripper points).
        tool_length: distance along the tool x axis included in T_flange_tool [m].
        gripper: the gripper.
        default_pitch: pitch used when an IK call gives none [rad], or None (free).
        drivers: per-driver default calibration tables, as written in the file.
        source: the file it was loaded from.
        table_z: height of the table plane in the world frame [m]; no link may go below it.
        link_radii: radius of each link's capsule [m], shape (dof + 1,): capsule i joins
            the origins of frames i and i + 1 of ``fk_frames`` (the last one the flange
            to the tool point). Capsule 0 is the base column and stands on the table.
        frames: the chain as one ``JointFrame`` per joint, for ``convention = "frames"``
            (empty for DH models).

    The compiled form the kinematics functions use is held beside the model
    (``armkit.kinematics``), never on it: a model is immutable.
    """

    name: str
    description: str
    convention: Convention
    joints: tuple[Joint, ...]
    dh: tuple[DHRow, ...]
    T_flange_tool: NDArray[np.float64]
    tool_length: float = 0.0
    gripper: Gripper = field(default_factory=Gripper)
    default_pitch: float | None = None
    drivers: dict[str, Any] = field(default_factory=dict)
    source: Path | None = None
    table_z: float = 0.0
    link_radii: tuple[float, ...] = ()
    frames: tuple[JointFrame, ...] = field(default=(), repr=False)

    @property
    def dof(self) -> int:
        """Number of joints."""
        return len(self.joints)

    @property
    def joint_names(self) -> tuple[str, ...]:
        """Joint names in chain order."""
        return tuple(j.name for j in self.joints)

    @property
    def lower(self) -> NDArray[np.float64]:
        """Lower limits [rad], shape (dof,)."""
        return np.array([j.lower for j in self.joints])

    @property
    def upper(self) -> NDArray[np.float64]:
        """Upper limits [rad], shape (dof,)."""
        return np.array([j.upper for j in self.joints])

    @property
    def home(self) -> NDArray[np.float64]:
        """Home pose [rad], shape (dof,)."""
        return np.array([j.home for j in self.joints])

    def joint_index(self, name: str) -> int:
        """Index of the joint called ``name``; ValueError lists the valid names."""
        names = self.joint_names
        if name not in names:
            raise InputError(
                f"unknown joint {name!r} for {self.name}; joints are {', '.join(names)}"
            )
        return names.index(name)

    def within_limits(self, q: NDArray[np.float64], slack: float = 1e-9) -> NDArray[np.bool_]:
        """True where every joint of q [rad], shape (..., dof), is inside its limits."""
        inside: NDArray[np.bool_] = np.all(
            (q >= self.lower - slack) & (q <= self.upper + slack), axis=-1
        )
        return inside

    def with_tool_length(self, length: float) -> ArmModel:
        """The same arm with the tool's length along its approach axis set to ``length`` [m]:
        0 (no tool: the flange point) or 0.01 mm..10 m, as a model file's ``tool.length_mm``.

        Raises:
            InputError: ``length`` is not such a number (negative, NaN, a bool, text, or
                over 10 m: 130 is likely 130 mm given as metres, 0.13).
        """
        length = _tool_length(length)
        T = self.T_flange_tool.copy()
        T[:3, 3] += T[:3, 0] * (length - self.tool_length)
        return replace(self, T_flange_tool=T, tool_length=length)

    def at_servo_limits(self) -> ArmModel:
        """The same arm planned at its servos' own limits (``Joint.peak_velocity`` and
        ``peak_acceleration`` as its max_*): what music's strikes are timed with."""
        joints = tuple(
            replace(j, max_velocity=j.peak_velocity, max_acceleration=j.peak_acceleration)
            for j in self.joints
        )
        return replace(self, joints=joints)

    def with_grip_width(self, width: float) -> ArmModel:
        """The same arm with the grip point moved for a gripper opening ``width`` [m]
        (002's grip-length polynomial); unchanged for grippers of fixed length."""
        g = self.gripper
        if not g.width_min - 1e-12 <= width <= g.width_max + 1e-12:
            raise InputError(
                f"grip width {width * 1000:.1f} mm is outside {self.name}'s range "
                f"{g.width_min * 1000:.1f}..{g.width_max * 1000:.1f} mm"
            )
        length = g.length_at(width)
        return self if length is None else self.with_tool_length(length)


def _tool_length(length: object) -> float:
    """``length`` [m] checked as ``ArmModel.with_tool_length`` takes it (the model file's
    rule for a tool length, ``_check.Checker.length``), as a float."""
    v = float(length) if is_number(length) else math.nan  # type: ignore[arg-type]
    if v == 0.0 or MIN_LENGTH_MM <= v * 1000.0 <= MAX_LENGTH_MM:  # NaN fails
        return v
    allowed = (
        f"tool length must be 0 (no tool: the flange point) or {MIN_LENGTH_MM:g} mm.."
        f"{MAX_LENGTH_MM / 1000.0:g} m, given in metres (130 mm is 0.13)"
    )
    if not math.isfinite(v):
        raise InputError(f"{allowed}, got {shown(length)}")
    slip = f"; is {shown(v)} in mm? give {shown(v / 1000.0)}" if v * 1000.0 > MAX_LENGTH_MM else ""
    raise InputError(f"{allowed}, got {shown(v)} m ({brief(v * 1000.0)} mm){slip}")
