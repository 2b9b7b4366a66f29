"""Serial arms from URDF files: the chain from the root link to a tip link.

``armkit --arm robot.urdf`` (or ``robot.urdf#tip_link``) reads the file with
yourdfpy (the ``urdf`` extra). The chain runs from the root link through the
revolute (or continuous) joints to the tip: the named link, else the last
link of the one moving branch followed by its fixed joints while they do not
branch (an ``end_effector`` or ``tool`` link). Fixed joints on the way are
folded into the next joint's frame; limits come from ``<limit>`` (a
continuous joint gets one turn, -180..180 deg). Every refusal names the file
and the element.
"""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import NDArray

from .._errors import ModelError
from ._types import ArmModel, Joint, JointFrame

F64 = NDArray[np.float64]
MOVING = ("revolute", "continuous")
MAX_ORIGIN = 100.0  # [m]: a joint origin farther from its parent is no arm (lengths in mm?)


def load_urdf(name_or_path: str | Path) -> ArmModel:
    """The serial arm of a URDF file, ``path`` or ``path#tip_link``.

    Raises:
        ModelError: the file is missing or not URDF, yourdfpy is not installed, or the
            chain is not a serial arm of revolute joints; the message names the element.
    """
    text, _, tip = str(name_or_path).partition("#")
    path = Path(text).expanduser()
    if path.is_dir():
        raise ModelError(f"{path}: is a directory; give a .urdf file")
    if not path.is_file():
        raise ModelError(f"{path}: no such URDF file")
    try:
        tree = ET.parse(path)
    except ET.ParseError as exc:
        raise ModelError(f"{path}: not valid XML: {exc}") from None
    _check_origins(path, tree.getroot())
    try:
        import yourdfpy
    except ImportError:
        raise ModelError(
            f"{path}: reading URDF needs the 'urdf' extra: pip install 'armkit[urdf]'"
        ) from None
    robot = yourdfpy.URDF.load(
        str(path), build_scene_graph=False, load_meshes=False, load_collision_meshes=False
    ).robot
    chain, tool = _chain(path, robot, tip or None)
    return _model(path, robot.name or path.stem, chain, tool)


def _chain(path: Path, robot: Any, tip: str | None) -> tuple[list[Any], F64]:
    """The moving joints from the root to the tip, and the tip in the last one's frame."""
    children: dict[str, list[Any]] = {}
    for j in robot.joints:
        children.setdefault(j.parent, []).append(j)
    child_links = {j.child for j in robot.joints}
    roots = [link.name for link in robot.links if link.name not in child_links]
    if len(roots) != 1:
        raise ModelError(f"{path}: <robot>: needs one root link, found {roots or 'none'}")
    names = {link.name for link in robot.links}
    if tip is not None and tip not in names:
        raise ModelError(f"{path}: <link name='{tip}'>: no such link; links are {sorted(names)}")
    joints, pending, link = [], np.eye(4), roots[0]
    while link != tip:
        nxt = _next_joint(path, children.get(link, []), tip, children)
        if nxt is None:
            break
        if nxt.type not in (*MOVING, "fixed"):
            raise ModelError(
                f"{path}: <joint name='{nxt.name}'>: type '{nxt.type}' is not supported; "
                "armkit arms have revolute (or continuous) joints"
            )
        origin = pending @ (np.eye(4) if nxt.origin is None else np.asarray(nxt.origin))
        if nxt.type == "fixed":
            pending = origin
        else:
            joints.append((nxt, origin))
            pending = np.eye(4)
        link = nxt.child
    if not joints:
        other = [j for j in children.get(link, []) if j.type not in (*MOVING, "fixed")]
        if other:
            raise ModelError(
                f"{path}: <joint name='{other[0].name}'>: type '{other[0].type}' is not "
                f"supported; armkit arms have revolute (or continuous) joints and there is "
                f"none from '{roots[0]}' to it"
            )
        raise ModelError(f"{path}: <robot>: no revolute joint from '{roots[0]}' to the tip")
    return joints, pending


def _check_origins(path: Path, root: ET.Element) -> None:
    """Every ``<joint><origin>``: xyz finite and within ``MAX_ORIGIN`` [m], rpy finite [rad]
    (a length in mm, or a NaN, refused here rather than as an arm kilometres long)."""
    for joint in root.iter("joint"):
        origin = joint.find("origin")
        if origin is None:
            continue
        where = f"{path}: <joint name='{joint.get('name')}'>: <origin>"
        for key in ("xyz", "rpy"):
            text = origin.get(key, "0 0 0")
            try:
                values = [float(v) for v in text.split()]
            except ValueError:
                values = []
            if len(values) != 3 or not all(math.isfinite(v) for v in values):
                unit = "m" if key == "xyz" else "rad"
                raise ModelError(f'{where} {key}="{text}" must be 3 finite numbers [{unit}]')
            far = math.hypot(*values)
            if key == "xyz" and far > MAX_ORIGIN:
                raise ModelError(
                    f'{where} xyz="{text}" is {far:.3g} m from the parent joint; URDF lengths '
                    f"are metres and armkit takes up to {MAX_ORIGIN:g} m (76.5 mm is 0.0765)"
                )


def _next_joint(path: Path, out: list[Any], tip: str | None, children: dict[str, list[Any]]) -> Any:
    """The joint to follow from a link: towards the named tip, else the one leading to
    moving joints, else the one fixed joint; None at the end of the chain."""

    def reaches(j: Any, want: Any) -> bool:
        return bool(want(j)) or any(reaches(k, want) for k in children.get(j.child, []))

    if tip is not None:
        ways = [j for j in out if reaches(j, lambda k: k.child == tip)]
    else:
        ways = [j for j in out if reaches(j, lambda k: k.type in MOVING)]
        if not ways:
            fixed = [j for j in out if j.type == "fixed"]
            ways = fixed if len(fixed) == 1 else []
    if len(ways) > 1:
        names = ", ".join(repr(j.name) for j in ways)
        raise ModelError(
            f"{path}: the chain branches into joints {names}; name the tip link (FILE.urdf#LINK)"
        )
    return ways[0] if ways else None


def _model(path: Path, name: str, chain: list[Any], tool: F64) -> ArmModel:
    joints, frames = [], []
    for j, origin in chain:
        axis = np.array([1.0, 0.0, 0.0]) if j.axis is None else np.asarray(j.axis, dtype=float)
        if not np.isfinite(axis).all() or np.linalg.norm(axis) < 1e-9:
            raise ModelError(f"{path}: <joint name='{j.name}'>: <axis> must be a nonzero vector")
        lo, hi = -math.pi, math.pi
        if j.type == "revolute":
            if j.limit is None or j.limit.lower is None or j.limit.upper is None:
                raise ModelError(
                    f"{path}: <joint name='{j.name}'>: <limit lower upper> is required"
                )
            lo, hi = float(j.limit.lower), float(j.limit.upper)
            if not lo < hi:
                raise ModelError(
                    f"{path}: <joint name='{j.name}'>: <limit> lower must be < upper, got {lo:.6g}, {hi:.6g}"
                )
        speed = j.limit.velocity if j.limit is not None and j.limit.velocity else math.radians(90)
        home = 0.0 if lo < 0.0 < hi else 0.5 * (lo + hi)  # zero at a limit: the middle
        joints.append(Joint(j.name, lo, hi, home, max_velocity=float(speed)))
        frames.append(
            JointFrame(
                np.asarray(origin, dtype=float), tuple((axis / np.linalg.norm(axis)).tolist())
            )
        )  # type: ignore[arg-type]
    return ArmModel(
        name=name,
        description=f"from {path.name}",
        convention="frames",
        joints=tuple(joints),
        dh=(),
        T_flange_tool=tool,
        source=path,
        link_radii=(0.015,) * (len(joints) + 1),
        frames=tuple(frames),
    )
