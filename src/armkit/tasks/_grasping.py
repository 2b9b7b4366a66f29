"""Picking a cube up and putting it down, as 001 does: from the top where the
arm reaches, else from the side with the grasp point shifted up clear of the
holders; down through waypoints, close, back up the same way."""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
from numpy.typing import NDArray

from ..kinematics import fk
from ..model import ArmModel
from ..scene import MIN_COVER, Cube, Held, Rect, grasp, settle, support_under
from ._plan import TaskError
from ._state import Context, State, down, grip, solve, up

F64 = NDArray[np.float64]
TOP, SIDE = -math.pi / 2, 0.0
JAW_ROOM = 0.010  # [m] opened this much wider than the cube on each side
SIDE_MARGIN = 0.002  # [m] between a level gripper's links and the surface round the cube
UP = np.array([0.0, 0.0, 1.0])
OTHER_FACE = "would land on another face"  # the end of a put-down's refusal for it


def how(pitch: float) -> str:
    """``"from the top"``, ``"from the side"`` or ``"at pitch -45"``."""
    if abs(pitch - TOP) < 1e-9:
        return "from the top"
    return "from the side" if abs(pitch) < 1e-9 else f"at pitch {math.degrees(pitch):.0f}"


def gripper_model(ctx: Context, cube: Cube) -> tuple[ArmModel, float]:
    """The model with the jaws closed on ``cube`` (the grip point of a scissor
    gripper moves with the width), and the opening before closing [m]."""
    g = ctx.model.gripper
    opening = min(g.width_max, cube.size + 2 * JAW_ROOM)
    if not g.width_min < cube.size < opening - 1e-3:
        raise TaskError(
            f"{ctx.task}: the {ctx.model.name} gripper opens {g.width_min * 1000:.0f}.."
            f"{g.width_max * 1000:.0f} mm; it cannot grasp {cube.name} ({cube.size * 1000:.0f} mm)",
            step=ctx.task,
        )
    return ctx.model.with_grip_width(cube.size), opening


def radial(st: State, point: F64) -> F64:
    """Unit vector from the arm's base axis out to ``point`` (scene frame), horizontal."""
    r = point - st.scene.T_world_base[:3, 3]
    r[2] = 0.0
    n = float(np.linalg.norm(r))
    return r / n if n > 1e-9 else np.array([1.0, 0.0, 0.0])


def check_uncovered(ctx: Context, st: State, name: str) -> None:
    """TaskError if another cube rests on cube ``name`` (it must be moved first)."""
    for other in st.scene.cubes:
        if other.name == name:
            continue
        foot = Rect(other.position[:2].copy(), (other.size / 2,) * 2, other.yaw)
        under = support_under(st.scene.without_cube(other.name), foot, float(other.position[2]))
        if under.on == name:
            raise TaskError(
                f"{ctx.task}: cannot pick {name}: it is under {other.name}; move {other.name} first",
                step=f"pick {name}",
            )


def side_shift(ctx: Context, st: State, cube: Cube) -> float:
    """How far above its centre [m] a level gripper must hold ``cube`` so that its
    links (wrist and gripper radii) clear the surface round the cube: a board's
    top face round a socket, the cube below in a stack, the table.

    Raises:
        TaskError: that is too high for the pads to hold the cube.
    """
    r = max(ctx.model.link_radii[-2:], default=0.015)
    foot = Rect(cube.position[:2].copy(), (cube.size / 2 + r,) * 2, cube.yaw)
    surface = support_under(st.scene.without_cube(cube.name), foot, float(cube.position[2]) + 1.0)
    level = max(float(cube.center[2]), surface.z + r + SIDE_MARGIN)
    shift = level - float(cube.center[2])
    most = cube.size / 2 + ctx.model.gripper.finger_width * (0.5 - MIN_COVER)
    if shift > most + 1e-9:
        held = cube.top_z - level + ctx.model.gripper.finger_width / 2
        hold = (
            f"its jaws would hold only the top {held * 1000:.1f} mm of {cube.name}"
            if held > 0
            else f"its jaws would pass above {cube.name}, whose top is at {cube.top_z * 1000:.1f} mm"
        )
        raise TaskError(
            f"{ctx.task}: from the side, the gripper must stay {level * 1000:.1f} mm high to "
            f"clear the {surface.on}: {hold}",
            step=f"pick {cube.name} from the side",
        )
    return shift


def grasp_point(st: State, cube: Cube, pitch: float, shift: float) -> F64:
    """The tool point on ``cube``: its centre, moved ``shift`` [m] up for a side
    grasp or out from the base for a top grasp (so that turned onto its side it is
    ``shift`` up)."""
    c = cube.center
    along: F64 = UP if abs(pitch - TOP) > 1e-9 else radial(st, c)
    out: F64 = c + shift * along
    return out


def pick(ctx: Context, st: State, name: str, pitch: float, shift: float) -> State:
    """Open, come down on cube ``name``, close on it, go back up holding it."""
    cube = st.scene.cube(name)
    kin, opening = gripper_model(ctx, cube)
    label = f"pick {name} {how(pitch)}"
    if st.opening is None or st.opening < opening - 1e-6:
        st = grip(ctx, st, opening, f"open to {opening * 1000:.0f} mm")
    p = grasp_point(st, cube, pitch, shift)
    st = down(ctx, st, p, pitch, label, kin=kin, ignore=frozenset({name}))
    T_tool = st.scene.T_world_base @ fk(kin, st.q)
    found = grasp(ctx.model.gripper, T_tool, opening, cube)
    if not found.ok or found.T_tool_object is None:
        raise TaskError(
            f"{ctx.task}: step '{label}': the jaws would miss: {found.reason}", step=label
        )
    st = grip(ctx, st, ctx.model.gripper.width_min, f"close on {name}")
    st = replace(st, held=Held(cube, found.T_tool_object), scene=st.scene.without_cube(name))
    return up(ctx, st, p, pitch, label, kin=kin, ignore=frozenset())


def place(
    ctx: Context, st: State, bottom: F64, pitch: float, where: str, *, turn: bool = False
) -> State:
    """Come down with the held cube so its lowest face's centre is at ``bottom``
    (scene frame) [m], open, go back up. The cube keeps the face up it had when it
    was picked unless ``turn`` (001's rotation); a pitch that would lay it on
    another face is a TaskError."""
    if st.held is None:
        raise TaskError(f"{ctx.task}: nothing is held to put down", step=ctx.task)
    cube = st.held.cube
    kin, opening = gripper_model(ctx, cube)
    label = f"put {cube.name} {where} {how(pitch)}"
    p, T_cube = _tool_point(ctx, st, kin, bottom + UP * cube.size / 2, pitch, label)
    rest = settle(st.scene, cube, T_cube)
    if rest.outcome != "placed":
        raise TaskError(
            f"{ctx.task}: step '{label}': {cube.name} would be {rest.outcome} on {rest.on}",
            step=label, why=f"{cube.name} would be {rest.outcome} on {rest.on}",
            remedy="put it on a flat, free place",
        )  # fmt: skip
    if not turn and rest.cube.up_face != cube.up_face:
        was = held_pitch(st.held)
        raise TaskError(
            f"{ctx.task}: step '{label}': {cube.name} would land {rest.cube.up_face} up, "
            f"not {cube.up_face} up as it was",
            step=label, why=f"{cube.name} {OTHER_FACE}",
            remedy=f"put it down {how(was)}, as it was picked, or turn it with rotate-cube",
        )  # fmt: skip
    st = down(ctx, st, p, pitch, label, kin=kin, ignore=frozenset())
    st = grip(ctx, st, opening, f"release {cube.name}")
    st = replace(st, held=None, scene=replace(st.scene, cubes=(*st.scene.cubes, rest.cube)))
    return up(ctx, st, p, pitch, label, kin=kin, ignore=frozenset({cube.name}))


def held_pitch(held: Held) -> float:
    """The pitch [rad] at which ``held`` goes down with the face up it was picked
    with: the direction that was up, in the tool frame, is (sin pitch, ., .) for a
    tool whose x axis points along the approach (every base-yaw arm)."""
    cube = held.cube
    R_obj = cube.T[:3, :3]  # as it stood when picked
    up_in_tool = held.T_tool_object[:3, :3] @ (R_obj.T @ UP)
    return math.asin(max(-1.0, min(1.0, float(up_in_tool[0]))))


def _tool_point(
    ctx: Context, st: State, kin: ArmModel, centre: F64, pitch: float, label: str
) -> tuple[F64, F64]:
    """The tool point [m] that puts the held cube's centre at ``centre`` (scene
    frame) at ``pitch``, and the cube's pose there (4, 4): a first guess from the
    tool's heading there, then fixed-point steps through IK and FK."""
    assert st.held is not None
    offset = st.held.T_tool_object[:3, 3]
    p = centre - _heading(ctx, st, kin, centre, pitch) @ offset
    T_cube = np.eye(4)
    for _ in range(6):
        q = solve(kin, st.scene.to_base(p), pitch, st.q, ctx.task, label)
        T_cube = st.scene.T_world_base @ fk(kin, q) @ st.held.T_tool_object
        error = centre - T_cube[:3, 3]
        if float(np.linalg.norm(error)) < 1e-6:
            break
        p = p + error
    return p, T_cube


def _heading(ctx: Context, st: State, kin: ArmModel, point: F64, pitch: float) -> F64:
    """A guess of the tool's rotation (3, 3) at ``point`` and ``pitch`` for an arm
    whose jaws close across its vertical plane (every base-yaw arm): approach in
    that plane, the jaw axis level and on the same side as now."""
    jaw = 2 if ctx.model.gripper.jaw_axis == "z" else 1
    R_now = (st.scene.T_world_base @ fk(kin, st.q))[:3, :3]
    out = radial(st, point)
    side = np.array([-out[1], out[0], 0.0])
    now_out = radial(st, (st.scene.T_world_base @ fk(kin, st.q))[:3, 3])
    sign = math.copysign(1.0, float(R_now[:, jaw] @ np.array([-now_out[1], now_out[0], 0.0])))
    x = math.cos(pitch) * out + math.sin(pitch) * UP
    R = np.zeros((3, 3))
    R[:, 0], R[:, jaw] = x, sign * side
    R[:, 3 - jaw] = np.cross(R[:, jaw], x) if jaw == 2 else np.cross(x, R[:, jaw])
    return R
