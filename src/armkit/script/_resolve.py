"""Values, targets and job arguments resolved to SI, with parameters bound.

A parameter bound to ``UNKNOWN`` (a procedure checked before it is called)
resolves to None: the checker then skips what depends on it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from ..kinematics import fk
from ..model import ArmModel
from ._ast import XYZ, Here, JobArg, JointList, Loc, Num, PoseName, Quantity, TargetExpr, Value
from ._diagnostics import suggest
from ._jobs import JOBS, JobParam
from ._units import NOUN, Dim, UnitProblem, to_si

if TYPE_CHECKING:
    from ..scene import Scene

F64 = NDArray[np.float64]
SHEET_PRESETS = ("A4", "A5", "A6")


class Fail(Exception):
    """A statement cannot be resolved: where and why."""

    def __init__(self, loc: Loc, message: str) -> None:
        super().__init__(message)
        self.loc = loc
        self.message = message


@dataclass(frozen=True)
class Point:
    """A gripper point [m], shape (3,), and approach pitch [rad] (None: the model's default, else free)."""

    xyz: F64
    pitch: float | None

    def __repr__(self) -> str:
        p = "free" if self.pitch is None else f"{math.degrees(self.pitch):.6g}"
        return f"Point({', '.join(f'{v:.9g}' for v in self.xyz)}, pitch {p})"

    def describe(self) -> str:
        """As a script writes it: ``xyz 180 0 80 pitch -90`` [mm, deg]."""
        xyz = " ".join(f"{v * 1000:.4g}" for v in self.xyz)
        return f"xyz {xyz}" + (
            "" if self.pitch is None else f" pitch {math.degrees(self.pitch):.4g}"
        )


@dataclass(frozen=True)
class JointPose:
    """Joint angles [rad], shape (dof,)."""

    q: F64

    def __repr__(self) -> str:
        return f"JointPose({', '.join(f'{v:.9g}' for v in self.q)})"

    def describe(self) -> str:
        """As a script writes it: ``joints 0 -60 20 40`` [deg]."""
        return "joints " + " ".join(f"{math.degrees(v):.3f}" for v in self.q)


Target = Point | JointPose


class _Unknown:
    def __repr__(self) -> str:
        return "UNKNOWN"


UNKNOWN: Any = _Unknown()
Arg = Num | str | _Unknown


@dataclass(frozen=True)
class SceneInfo:
    """What the script knows of its scene.

    Attributes:
        label: the file or name it was chosen by.
        names: every object, place and sheet name; None if the scene could not be
            loaded by this armkit (names are then not checked).
        scene: the loaded scene, passed to jobs (None if not loaded).
    """

    label: str
    names: frozenset[str] | None
    scene: object | None


def job_scene(info: SceneInfo | None) -> Scene | None:
    """The ``Scene`` jobs get: the script's, or the empty table if it names none
    (None: its scene could not be loaded by this armkit)."""
    if info is None:
        from ..scene import load_scene

        return load_scene("empty")
    from ..scene import Scene as Loaded

    return info.scene if isinstance(info.scene, Loaded) else None


class Resolver:
    """Turns written values into SI numbers and targets.

    Attributes:
        model: the arm.  poses: named targets (None: not known before it runs).
        bindings: one dict of parameter bindings per active procedure call.
        scene: the scene, or None.  base_dir: where relative file names start.
    """

    def __init__(self, model: ArmModel, scene: SceneInfo | None, base_dir: Path) -> None:
        self.model, self.scene, self.base_dir = model, scene, base_dir
        self.poses: dict[str, Target | None] = {}
        self.bindings: list[dict[str, Arg]] = [{}]

    def number(self, value: Value, dim: Dim) -> float | None:
        """``value`` in SI for ``dim`` (None if it depends on an unknown parameter)."""
        if isinstance(value, Num):
            return self._si(value, dim, value.loc)
        arg = self.binding(value.name, value.loc)
        if arg is UNKNOWN:
            return None
        if isinstance(arg, Num):
            si = self._si(arg, dim, value.loc)
            return -si if value.negate else si
        raise Fail(value.loc, f"{value.name} is {arg!r}, a name, but {NOUN[dim]} is needed")

    def binding(self, name: str, loc: Loc) -> Arg:
        """What parameter ``name`` is bound to; Fail if there is no such parameter."""
        scope = self.bindings[-1]
        if name in scope:
            return scope[name]
        hint = suggest(name, scope) if scope else ""
        raise Fail(loc, f"undefined name {name!r}; a number is needed here{hint}")

    def target(self, expr: TargetExpr, here: JointPose | None) -> Target | None:
        """The target ``expr`` names, with ``here`` the arm's current pose."""
        if isinstance(expr, XYZ):
            coords = [self.number(v, "length") for v in (expr.x, expr.y, expr.z)]
            pitch = None if expr.pitch is None else self.number(expr.pitch, "angle")
            if any(c is None for c in coords) or (expr.pitch is not None and pitch is None):
                return None
            return Point(np.array(coords, dtype=np.float64), pitch)
        if isinstance(expr, JointList):
            return self._joints(expr)
        if isinstance(expr, Here):
            return here
        return self.pose(expr)

    def pose(self, ref: PoseName) -> Target | None:
        """The pose ``ref`` names (through a parameter if it is one)."""
        name = self.name_of(ref)
        if name is None:
            return None
        if name not in self.poses:
            hint = suggest(name, [*self.poses, *self.bindings[-1]])
            raise Fail(
                ref.loc, f"undefined pose {name!r} (define it with 'pose {name} = ...'){hint}"
            )
        return self.poses[name]

    def name_of(self, ref: PoseName) -> str | None:
        """The name written, or the name a parameter of that name is bound to."""
        scope = self.bindings[-1]
        if ref.name not in scope:
            return ref.name
        arg = scope[ref.name]
        if arg is UNKNOWN:
            return None
        if isinstance(arg, Num):
            raise Fail(ref.loc, f"{ref.name} is the number {arg.value:g}, but a name is needed")
        return str(arg)

    def joint(self, name: str, loc: Loc) -> str:
        """``name`` if the arm has that joint (else Fail with did-you-mean)."""
        names = self.model.joint_names
        if name not in names:
            listed = ", ".join(names)
            raise Fail(
                loc,
                f"{self.model.name} has no joint {name!r} (joints: {listed}){suggest(name, names)}",
            )
        return name

    def job_args(
        self, command: str, args: tuple[JobArg, ...], here: JointPose | None
    ) -> dict[str, object]:
        """Each argument of a job as its function receives it (see ``_jobs``)."""
        spec = {p.name: p for p in JOBS[command].params}
        return {a.name: self._job_arg(spec[a.name], a, here) for a in args}

    def _job_arg(self, p: JobParam, a: JobArg, here: JointPose | None) -> object:
        v = a.value
        if isinstance(v, bool):
            return v
        if isinstance(v, Quantity):
            si = self.number(v.value, v.dim)
            return int(si) if si is not None and v.dim == "count" else si
        if isinstance(v, tuple):
            return tuple(self._object(r, p) for r in v)
        if isinstance(v, str):
            return self._file(v, a.loc) if p.kind == "file" else v
        if p.kind == "object" and isinstance(v, PoseName):
            return self._object(v, p)
        if isinstance(v, PoseName):
            name = self.name_of(v)
            if name is None:
                return None
            if name not in self.poses:
                return self._place(v, name, p)
        target = self.target(v, here)
        return None if target is None else self.point_of(target)

    def point_of(self, target: Target) -> F64:
        """The gripper point [m], shape (3,), of a target."""
        if isinstance(target, Point):
            return target.xyz
        return np.asarray(fk(self.model, target.q)[:3, 3], dtype=np.float64)

    def _place(self, ref: PoseName, name: str, p: JobParam) -> str | None:
        if self.scene is None:
            hint = suggest(name, self.poses)
            raise Fail(
                ref.loc,
                f"{name!r} is not a pose{hint}, and no scene is chosen to find it in; "
                f"define 'pose {name} = ...' or add 'scene FILE' at the top",
            )
        return self._object(ref, p)

    def _object(self, ref: PoseName, p: JobParam) -> str | None:
        name = self.name_of(ref)
        if name is None:
            return None
        if p.name == "sheet" and name in SHEET_PRESETS:
            return name
        if self.scene is None:
            raise Fail(
                ref.loc,
                f"{name!r} must be an object of the scene, and no scene is chosen; add 'scene FILE' at the top",
            )
        known = self.scene.names
        if known is not None and name not in known:
            raise Fail(
                ref.loc, f"the scene {self.scene.label} has no {name!r}{suggest(name, known)}"
            )
        return name

    def _file(self, text: str, loc: Loc) -> Path:
        path = Path(text).expanduser()
        path = path if path.is_absolute() else self.base_dir / path
        if not path.is_file():
            raise Fail(loc, f"no file {text!r} (looked for {path})")
        return path

    def _joints(self, expr: JointList) -> JointPose | None:
        dof = self.model.dof
        if len(expr.angles) != dof:
            names = ", ".join(self.model.joint_names)
            raise Fail(
                expr.loc,
                f"{self.model.name} has {dof} joints ({names}), got {len(expr.angles)} angles",
            )
        q = [self.number(v, "angle") for v in expr.angles]
        if any(a is None for a in q):
            return None
        return JointPose(np.array(q, dtype=np.float64))

    def _si(self, num: Num, dim: Dim, loc: Loc) -> float:
        try:
            si = to_si(num.value, num.unit, dim)
        except UnitProblem as exc:
            raise Fail(loc, str(exc)) from None
        if not math.isfinite(si):
            raise Fail(loc, f"{num.value} is not a finite number")
        return si
