"""Load and validate arm model files (TOML, millimetres and degrees)."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import NDArray

from .._errors import ModelError
from .._toml_files import read_toml, resolve, shipped
from .._toml_where import located
from ._check import MAX_LENGTH_MM
from ._check import NUM as _NUM
from ._check import Checker as _Checker
from ._frame_rows import chain_frames, rpy_matrix
from ._sections import check_driver_sections
from ._types import ArmModel, DHRow, Gripper, Joint

_TOP = {
    "name": str,
    "description": str,
    "dh_convention": str,
    "default_pitch_deg": _NUM,
    "joints": list,
    "tool": dict,
    "gripper": dict,
    "drivers": dict,
    "notes": str,
    "table_z_mm": _NUM,
    "links": dict,
    "base": dict,
}
_REQUIRED_TOP = ("name", "dh_convention", "joints")
_JOINT = {
    "name": str,
    "limits_deg": list,
    "home_deg": _NUM,
    "max_speed_dps": _NUM,
    "max_accel_dps2": _NUM,
    "servo_speed_dps": _NUM,
    "servo_accel_dps2": _NUM,
    "dh": dict,
    "frame": dict,
}
_REQUIRED_JOINT = ("name", "limits_deg", "home_deg")
_DH = {"a_mm": _NUM, "alpha_deg": _NUM, "d_mm": _NUM, "theta_offset_deg": _NUM, "flip": bool}
_REQUIRED_DH = ("a_mm", "alpha_deg", "d_mm")
_TOOL = {"xyz_mm": list, "rpy_deg": list, "length_mm": _NUM}
_GRIPPER = {
    "kind": str,
    "width_mm": list,
    "length_poly_mm": list,
    "closed_length_mm": _NUM,
    "jaw_axis": str,
    "finger_mm": list,
}
_GRIPPER_KINDS = ("parallel", "scissor", "timed")
_LINKS = {"radius_mm": object}  # a number or a list, checked in _link_radii
DEFAULT_LINK_RADIUS_MM = 15.0
MAX_LINK_RADIUS_MM = 200.0
MAX_JOINTS = 12
MAX_SPEED_DPS = 3600.0
MAX_ACCEL_DPS2 = 1e6
MAX_WIDTH_MM = 1000.0


def shipped_models() -> list[str]:
    """Names of the arm models shipped with armkit, sorted."""
    return shipped("armkit.model", "arms")


def is_urdf(name_or_path: str | Path) -> bool:
    """True for ``*.urdf`` and ``*.urdf#tip_link``."""
    return str(name_or_path).split("#", 1)[0].lower().endswith(".urdf")


def load_model(name_or_path: str | Path) -> ArmModel:
    """Load a shipped model by name (``"owi535"``) or a user's TOML file by path.

    Raises:
        ModelError: the file is missing, is not TOML, or a field is wrong; the
            message names the file, the field and what is allowed.
    """
    if is_urdf(name_or_path):  # a URDF file: FILE.urdf or FILE.urdf#TIP_LINK
        from ._urdf import load_urdf  # xml.etree only for a URDF

        return load_urdf(name_or_path)
    path = _resolve(name_or_path)
    data, text = read_toml(path, ModelError, "model file")
    try:
        return _build(data, path)
    except ModelError as exc:
        raise located(exc, text) from None


def _resolve(name_or_path: str | Path) -> Path:
    return resolve(
        name_or_path, "armkit.model", "arms", ModelError, kind="model", noun="arm",
        files=".toml or .urdf",
    )  # fmt: skip


def _build(data: dict[str, Any], path: Path) -> ArmModel:
    check = _Checker(path)
    check.table(data, "", _TOP, _REQUIRED_TOP)
    convention = data["dh_convention"]
    if convention not in ("standard", "modified", "frames"):
        raise check.fail(
            "dh_convention", f"must be 'standard', 'modified' or 'frames', got {convention!r}"
        )
    if not data["joints"] or len(data["joints"]) > MAX_JOINTS:
        raise check.fail("joints", f"needs 1..{MAX_JOINTS} [[joints]] entries")
    chain = "frame" if convention == "frames" else "dh"
    joints, rows = zip(
        *(_joint(check, j, k, chain) for k, j in enumerate(data["joints"])), strict=True
    )
    names = [j.name for j in joints]
    if len(set(names)) != len(names):
        raise check.fail("joints", f"joint names must be unique, got {', '.join(names)}")
    frames = chain_frames(check, data["joints"], data.get("base", {})) if chain == "frame" else ()
    if chain == "dh":
        if "base" in data:
            raise check.fail("base", "is for dh_convention = 'frames' (DH rows start at the world)")
        _check_axes(check, convention, rows)  # type: ignore[arg-type]  # DH rows here
    T, length = _tool(check, data.get("tool", {}))
    pitch = data.get("default_pitch_deg")
    model = ArmModel(
        name=check.identifier(data["name"], "name"),
        description=data.get("description", ""),
        convention=convention,  # type: ignore[arg-type]  # checked above
        joints=tuple(joints),
        dh=tuple(r for r in rows if r is not None),
        T_flange_tool=T,
        tool_length=length,
        gripper=_gripper(check, data.get("gripper", {})),
        default_pitch=None
        if pitch is None
        else math.radians(check.angle(pitch, "default_pitch_deg", 180.0)),
        drivers=dict(data.get("drivers", {})),
        source=path,
        table_z=check.length(data.get("table_z_mm", 0.0), "table_z_mm", signed=True) / 1000.0,
        link_radii=_link_radii(check, data.get("links", {}), len(joints) + 1),
        frames=frames,
    )
    check_driver_sections(check, model.drivers, model)
    return model


def _check_axes(check: _Checker, convention: str, rows: tuple[DHRow, ...]) -> None:
    """Refuse two joints on one axis: a link of no length (a = 0, alpha = 0) between
    joint k and joint k + 1 makes them one joint, and the chain degenerate."""
    for k in range(len(rows) - 1):
        row, field = (rows[k + 1], k + 1) if convention == "modified" else (rows[k], k)
        if row.a == 0.0 and abs(math.sin(row.alpha)) < 1e-12:
            raise check.fail(
                f"joints[{field}].dh",
                f"a_mm = 0 and alpha_deg = {math.degrees(row.alpha):g} put joints {k} and "
                f"{k + 1} on one axis (a link of no length); give the link its length a_mm",
            )


def _joint(check: _Checker, data: Any, k: int, chain: str) -> tuple[Joint, DHRow | None]:
    """One ``[[joints]]`` entry; ``chain`` is the table its place in the chain is given
    by: ``"dh"`` (a DH row, returned) or ``"frame"`` (read by ``chain_frames``)."""
    where = f"joints[{k}]"
    check.table(data, where, _JOINT, (*_REQUIRED_JOINT, chain))
    other = "frame" if chain == "dh" else "dh"
    if other in data:
        raise check.fail(
            f"{where}.{other}",
            f"this model's chain is given by '{chain}' tables (dh_convention), not '{other}'",
        )
    lo, hi = check.numbers(data["limits_deg"], f"{where}.limits_deg", 2)
    for i, limit in enumerate((lo, hi)):
        check.angle(limit, f"{where}.limits_deg[{i}]")
    if lo >= hi:
        raise check.fail(f"{where}.limits_deg", f"min must be < max, got [{lo}, {hi}]")
    home = float(data["home_deg"])
    if not lo <= home <= hi:
        raise check.fail(f"{where}.home_deg", f"{home} is outside limits [{lo}, {hi}]")
    speed = check.within(
        data.get("max_speed_dps", 90.0), f"{where}.max_speed_dps", 0, MAX_SPEED_DPS, "deg/s",
        open_low=True,
    )  # fmt: skip
    accel = check.within(
        data.get("max_accel_dps2", 360.0), f"{where}.max_accel_dps2", 0, MAX_ACCEL_DPS2,
        "deg/s^2", open_low=True,
    )  # fmt: skip
    servo_speed, servo_accel = (
        None if key not in data else math.radians(check.within(
            data[key], f"{where}.{key}", low, top, unit
        ))
        for key, low, top, unit in (
            ("servo_speed_dps", speed, MAX_SPEED_DPS, "deg/s (at least max_speed_dps)"),
            ("servo_accel_dps2", accel, MAX_ACCEL_DPS2, "deg/s^2 (at least max_accel_dps2)"),
        )
    )  # fmt: skip
    joint = Joint(
        name=check.identifier(data["name"], f"{where}.name"),
        lower=math.radians(lo),
        upper=math.radians(hi),
        home=math.radians(home),
        max_velocity=math.radians(speed),
        max_acceleration=math.radians(accel),
        servo_velocity=servo_speed,
        servo_acceleration=servo_accel,
    )
    return joint, _dh(check, data["dh"], f"{where}.dh") if chain == "dh" else None


def _dh(check: _Checker, data: Any, where: str) -> DHRow:
    check.table(data, where, _DH, _REQUIRED_DH)
    return DHRow(
        a=check.length(data["a_mm"], f"{where}.a_mm") / 1000.0,
        alpha=math.radians(check.angle(data["alpha_deg"], f"{where}.alpha_deg")),
        d=check.length(data["d_mm"], f"{where}.d_mm", signed=True) / 1000.0,
        theta_offset=math.radians(
            check.angle(data.get("theta_offset_deg", 0.0), f"{where}.theta_offset_deg")
        ),
        sign=-1.0 if data.get("flip", False) else 1.0,
    )


def _tool(check: _Checker, data: Any) -> tuple[NDArray[np.float64], float]:
    check.table(data, "tool", _TOOL, ())
    xyz = check.numbers(data.get("xyz_mm", [0, 0, 0]), "tool.xyz_mm", 3)
    rpy = check.numbers(data.get("rpy_deg", [0, 0, 0]), "tool.rpy_deg", 3)
    for k in range(3):
        check.length(xyz[k], f"tool.xyz_mm[{k}]", signed=True)
        check.angle(rpy[k], f"tool.rpy_deg[{k}]")
    length = check.length(data.get("length_mm", 0.0), "tool.length_mm") / 1000.0
    T = np.eye(4)
    T[:3, :3] = rpy_matrix(*(math.radians(v) for v in rpy))
    T[:3, 3] = np.array(xyz) / 1000.0 + T[:3, 0] * length
    return T, length


def _link_radii(check: _Checker, data: Any, count: int) -> tuple[float, ...]:
    """``[links] radius_mm``: one number for every link, or ``count`` numbers (dof + 1:
    the base column, one per joint's link, the tool) [mm]; default 15 mm each."""
    check.table(data, "links", _LINKS, ())
    value = data.get("radius_mm", DEFAULT_LINK_RADIUS_MM)
    if isinstance(value, list):
        radii = check.numbers(value, "links.radius_mm", count)
    else:
        check.type(value, "links.radius_mm", _NUM)
        radii = [float(value)] * count
    for k, r in enumerate(radii):
        if not 0.0 <= r <= MAX_LINK_RADIUS_MM:
            raise check.fail(
                f"links.radius_mm[{k}]", f"must be 0..{MAX_LINK_RADIUS_MM:.0f} mm, got {r}"
            )
    return tuple(r / 1000.0 for r in radii)


def _gripper(check: _Checker, data: Any) -> Gripper:
    check.table(data, "gripper", _GRIPPER, ())
    kind = data.get("kind", "parallel")
    if kind not in _GRIPPER_KINDS:
        raise check.fail(
            "gripper.kind", f"must be one of {', '.join(_GRIPPER_KINDS)}, got {kind!r}"
        )
    lo, hi = check.numbers(data.get("width_mm", [0, 0]), "gripper.width_mm", 2)
    for k, width in enumerate((lo, hi)):
        check.within(width, f"gripper.width_mm[{k}]", 0.0, MAX_WIDTH_MM, "mm")
    if lo > hi:
        raise check.fail("gripper.width_mm", f"min must be <= max, got [{lo}, {hi}]")
    poly_mm = check.numbers(data.get("length_poly_mm", []), "gripper.length_poly_mm", None)
    if len(poly_mm) > 6:
        raise check.fail("gripper.length_poly_mm", f"at most 6 coefficients, got {len(poly_mm)}")
    closed = data.get("closed_length_mm")
    jaw_axis = data.get("jaw_axis", "z")
    if jaw_axis not in ("y", "z"):
        raise check.fail("gripper.jaw_axis", f"must be 'y' or 'z' (tool axis), got {jaw_axis!r}")
    finger = check.numbers(data.get("finger_mm", [20.0, 20.0]), "gripper.finger_mm", 2)
    if not all(0.0 < f <= 500.0 for f in finger):
        raise check.fail("gripper.finger_mm", f"must be 2 lengths in (0, 500] mm, got {finger}")
    if closed is not None:
        check.length(closed, "gripper.closed_length_mm")
    for w in np.linspace(lo, hi, 11) if poly_mm else ():
        grip_length = sum(c * w**k for k, c in enumerate(poly_mm))
        if not 0.0 <= grip_length <= MAX_LENGTH_MM:
            raise check.fail(
                "gripper.length_poly_mm",
                f"gives a grip length of {grip_length:g} mm at {w:g} mm open; "
                f"it must stay 0..{MAX_LENGTH_MM:g} mm over the width range",
            )
    return Gripper(
        kind=kind,
        width_min=lo / 1000.0,
        width_max=hi / 1000.0,
        length_poly=tuple(c * 1000.0 ** (k - 1) for k, c in enumerate(poly_mm)),
        closed_length=None if closed is None else closed / 1000.0,
        jaw_axis=jaw_axis,
        finger_length=finger[0] / 1000.0,
        finger_width=finger[1] / 1000.0,
    )
