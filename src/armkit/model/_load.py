"""Load and validate arm model files (TOML, millimetres and degrees)."""

from __future__ import annotations

import math
import tomllib
from importlib import resources
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import NDArray

from .._errors import ModelError
from ._types import ArmModel, DHRow, Gripper, Joint
from ._urdf import is_urdf, load_urdf

_NUM = (int, float)
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
}
_REQUIRED_TOP = ("name", "dh_convention", "joints")
_JOINT = {
    "name": str,
    "limits_deg": list,
    "home_deg": _NUM,
    "max_speed_dps": _NUM,
    "max_accel_dps2": _NUM,
    "dh": dict,
}
_REQUIRED_JOINT = ("name", "limits_deg", "home_deg", "dh")
_DH = {"a_mm": _NUM, "alpha_deg": _NUM, "d_mm": _NUM, "theta_offset_deg": _NUM, "flip": bool}
_REQUIRED_DH = ("a_mm", "alpha_deg", "d_mm")
_TOOL = {"xyz_mm": list, "rpy_deg": list, "length_mm": _NUM}
_GRIPPER = {"kind": str, "width_mm": list, "length_poly_mm": list, "closed_length_mm": _NUM}
_GRIPPER_KINDS = ("parallel", "scissor", "timed")
_LINKS = {"radius_mm": object}  # a number or a list, checked in _link_radii
DEFAULT_LINK_RADIUS_MM = 15.0
MAX_LINK_RADIUS_MM = 200.0


def shipped_models() -> list[str]:
    """Names of the arm models shipped with armkit, sorted."""
    folder = resources.files("armkit.model") / "arms"
    return sorted(p.name[:-5] for p in folder.iterdir() if p.name.endswith(".toml"))


def load_model(name_or_path: str | Path) -> ArmModel:
    """Load a shipped model by name (``"owi535"``) or a user's TOML file by path.

    Raises:
        ModelError: the file is missing, is not TOML, or a field is wrong; the
            message names the file, the field and what is allowed.
    """
    if is_urdf(name_or_path):  # a URDF file: FILE.urdf or FILE.urdf#TIP_LINK
        return load_urdf(name_or_path)
    path = _resolve(name_or_path)
    try:
        data = tomllib.loads(path.read_text(encoding="utf-8"))
    except tomllib.TOMLDecodeError as exc:
        raise ModelError(f"{path}: not valid TOML: {exc}") from None
    except OSError as exc:
        raise ModelError(f"{path}: cannot read: {exc.strerror}") from None
    return _build(data, path)


def _resolve(name_or_path: str | Path) -> Path:
    text = str(name_or_path)
    if text.endswith(".toml") or "/" in text or "\\" in text:
        path = Path(text).expanduser()
        if not path.is_file():
            raise ModelError(f"{path}: no such model file")
        return path
    names = shipped_models()
    if text not in names:
        raise ModelError(
            f"unknown arm {text!r}; shipped arms are {', '.join(names)} (or give a path to a .toml file)"
        )
    return Path(str(resources.files("armkit.model") / "arms" / f"{text}.toml"))


class _Checker:
    """Type and key checks that name the file and the field."""

    def __init__(self, path: Path) -> None:
        self.path = path

    def fail(self, where: str, message: str) -> ModelError:
        return ModelError(f"{self.path}: field '{where}': {message}")

    def table(
        self, data: Any, where: str, schema: dict[str, Any], required: tuple[str, ...]
    ) -> None:
        if not isinstance(data, dict):
            raise self.fail(where, f"must be a table, got {type(data).__name__}")
        for key in data:
            if key not in schema:
                allowed = ", ".join(schema)
                raise self.fail(f"{where}.{key}".lstrip("."), f"unknown key; allowed: {allowed}")
        for key in required:
            if key not in data:
                raise self.fail(f"{where}.{key}".lstrip("."), "missing (required)")
        for key, value in data.items():
            self.type(value, f"{where}.{key}".lstrip("."), schema[key])

    def type(self, value: Any, where: str, kind: Any) -> None:
        if kind is _NUM and (isinstance(value, bool) or not isinstance(value, _NUM)):
            raise self.fail(where, f"must be a number, got {value!r}")
        if kind is _NUM and not math.isfinite(value):
            raise self.fail(where, f"must be finite, got {value!r}")
        if kind is not _NUM and not isinstance(value, kind):
            raise self.fail(where, f"must be a {kind.__name__}, got {type(value).__name__}")

    def numbers(self, value: Any, where: str, count: int | None) -> list[float]:
        if not isinstance(value, list) or (count is not None and len(value) != count):
            n = f"{count} numbers" if count is not None else "a list of numbers"
            raise self.fail(where, f"must be {n}, got {value!r}")
        for k, item in enumerate(value):
            self.type(item, f"{where}[{k}]", _NUM)
        return [float(v) for v in value]


def _build(data: dict[str, Any], path: Path) -> ArmModel:
    check = _Checker(path)
    check.table(data, "", _TOP, _REQUIRED_TOP)
    convention = data["dh_convention"]
    if convention not in ("standard", "modified"):
        raise check.fail("dh_convention", f"must be 'standard' or 'modified', got {convention!r}")
    if not data["joints"]:
        raise check.fail("joints", "needs at least one [[joints]] entry")
    joints, rows = zip(*(_joint(check, j, k) for k, j in enumerate(data["joints"])), strict=True)
    names = [j.name for j in joints]
    if len(set(names)) != len(names):
        raise check.fail("joints", f"joint names must be unique, got {names}")
    T, length = _tool(check, data.get("tool", {}))
    pitch = data.get("default_pitch_deg")
    return ArmModel(
        name=data["name"],
        description=data.get("description", ""),
        convention=convention,
        joints=tuple(joints),
        dh=tuple(rows),
        T_flange_tool=T,
        tool_length=length,
        gripper=_gripper(check, data.get("gripper", {})),
        default_pitch=None if pitch is None else math.radians(pitch),
        drivers=dict(data.get("drivers", {})),
        source=path,
        table_z=float(data.get("table_z_mm", 0.0)) / 1000.0,
        link_radii=_link_radii(check, data.get("links", {}), len(joints) + 1),
    )


def _joint(check: _Checker, data: Any, k: int) -> tuple[Joint, DHRow]:
    where = f"joints[{k}]"
    check.table(data, where, _JOINT, _REQUIRED_JOINT)
    lo, hi = check.numbers(data["limits_deg"], f"{where}.limits_deg", 2)
    if lo >= hi:
        raise check.fail(f"{where}.limits_deg", f"min must be < max, got [{lo}, {hi}]")
    home = float(data["home_deg"])
    if not lo <= home <= hi:
        raise check.fail(f"{where}.home_deg", f"{home} is outside limits [{lo}, {hi}]")
    for key in ("max_speed_dps", "max_accel_dps2"):
        if key in data and data[key] <= 0:
            raise check.fail(f"{where}.{key}", f"must be > 0, got {data[key]}")
    joint = Joint(
        name=data["name"],
        lower=math.radians(lo),
        upper=math.radians(hi),
        home=math.radians(home),
        max_velocity=math.radians(data.get("max_speed_dps", 90.0)),
        max_acceleration=math.radians(data.get("max_accel_dps2", 360.0)),
    )
    return joint, _dh(check, data["dh"], f"{where}.dh")


def _dh(check: _Checker, data: Any, where: str) -> DHRow:
    check.table(data, where, _DH, _REQUIRED_DH)
    return DHRow(
        a=data["a_mm"] / 1000.0,
        alpha=math.radians(data["alpha_deg"]),
        d=data["d_mm"] / 1000.0,
        theta_offset=math.radians(data.get("theta_offset_deg", 0.0)),
        sign=-1.0 if data.get("flip", False) else 1.0,
    )


def _tool(check: _Checker, data: Any) -> tuple[NDArray[np.float64], float]:
    check.table(data, "tool", _TOOL, ())
    xyz = check.numbers(data.get("xyz_mm", [0, 0, 0]), "tool.xyz_mm", 3)
    rpy = check.numbers(data.get("rpy_deg", [0, 0, 0]), "tool.rpy_deg", 3)
    length = float(data.get("length_mm", 0.0)) / 1000.0
    T = np.eye(4)
    T[:3, :3] = _rpy_matrix(*(math.radians(v) for v in rpy))
    T[:3, 3] = np.array(xyz) / 1000.0 + T[:3, 0] * length
    return T, length


def _rpy_matrix(roll: float, pitch: float, yaw: float) -> NDArray[np.float64]:
    """R = Rz(yaw) Ry(pitch) Rx(roll), shape (3, 3)."""
    cr, sr, cp, sp = math.cos(roll), math.sin(roll), math.cos(pitch), math.sin(pitch)
    cy, sy = math.cos(yaw), math.sin(yaw)
    return np.array(
        [
            [cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
            [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
            [-sp, cp * sr, cp * cr],
        ]
    )


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
    if lo > hi:
        raise check.fail("gripper.width_mm", f"min must be <= max, got [{lo}, {hi}]")
    poly_mm = check.numbers(data.get("length_poly_mm", []), "gripper.length_poly_mm", None)
    closed = data.get("closed_length_mm")
    return Gripper(
        kind=kind,
        width_min=lo / 1000.0,
        width_max=hi / 1000.0,
        length_poly=tuple(c * 1000.0 ** (k - 1) for k, c in enumerate(poly_mm)),
        closed_length=None if closed is None else closed / 1000.0,
    )
