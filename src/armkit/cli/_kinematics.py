"""``armkit fk``, ``ik`` and ``plot``: millimetres and degrees in, millimetres and degrees out."""

from __future__ import annotations

import argparse
import math
from typing import TYPE_CHECKING, Any

from .._errors import InputError
from .._files import check_output_path
from .._terminal import count, fixed
from ._args import IMAGE_SUFFIXES, angle, coordinate
from ._table import table

if TYPE_CHECKING:
    import numpy as np

    from ..model import ArmModel


def add_commands(sub: argparse._SubParsersAction[Any]) -> None:
    """Add ``fk``, ``ik`` and ``plot``."""
    p = sub.add_parser(
        "fk",
        help="joint angles (deg) -> gripper position (mm) and pitch (deg)",
        description="Forward kinematics: joint angles in degrees, in model order (see 'armkit show'), "
        "to the gripper point in mm and its pitch in degrees.",
    )
    p.add_argument("angles", nargs="+", type=angle, metavar="DEG", help="one angle per joint [deg]")
    p.add_argument("--json", action="store_true", help="print one JSON object")
    p.set_defaults(func=run_fk)
    p = sub.add_parser(
        "ik",
        help="gripper position (mm) [+ pitch] -> joint angles (deg)",
        description="Inverse kinematics: a gripper point X Y Z in mm (x forward, y left, z up) and "
        "optionally its pitch in degrees (0 = level, -90 = pointing down) to joint angles in degrees.",
    )
    for axis in "xyz":
        p.add_argument(axis, type=coordinate, metavar=axis.upper(), help=f"target {axis} [mm]")
    p.add_argument(
        "--pitch", type=angle, metavar="DEG", help="gripper pitch [deg]; default: the arm's own"
    )
    p.add_argument(
        "--all", action="store_true", help="print every solution (elbow up/down, over the shoulder)"
    )
    p.add_argument(
        "--method",
        choices=IK_METHODS,
        default="auto",
        help="solver: auto (closed form where the arm allows, else lm), analytic, lm, "
        "ccd, jacobian or random (default auto)",
    )
    p.add_argument("--json", action="store_true", help="print one JSON object")
    p.set_defaults(func=run_ik)
    p = sub.add_parser(
        "plot",
        help="draw the arm in a pose with each joint's axes (plot extra)",
        description="Draw the arm in the given pose (degrees) with x/y/z axis indicators on every joint frame.",
    )
    p.add_argument("angles", nargs="+", type=angle, metavar="DEG", help="one angle per joint [deg]")
    p.add_argument(
        "-o", "--output", default="pose.png", metavar="FILE", help="image file (default pose.png)"
    )
    p.set_defaults(func=run_plot)


IK_METHODS = ("auto", "analytic", "lm", "ccd", "jacobian", "random")


def joint_angles(m: ArmModel, degrees: list[float]) -> np.ndarray:
    """Degrees from the command line -> radians, checked for count and finiteness."""
    import numpy as np

    if len(degrees) != m.dof:
        names = ", ".join(m.joint_names)
        raise InputError(
            f"{m.name} needs {m.dof} joint angles in degrees ({names}), got {len(degrees)}"
        )
    if not all(math.isfinite(d) for d in degrees):
        shown = ", ".join(f"{d:g}" for d in degrees)
        raise InputError(f"joint angles must be finite numbers of degrees, got {shown}")
    return np.radians(degrees)


def run_fk(args: argparse.Namespace) -> int:
    import json

    from ..kinematics import fk, pitch_of
    from ..model import load_model

    m = load_model(args.arm)
    q = joint_angles(m, args.angles)
    T = fk(m, q)
    pos = (T[:3, 3] * 1000).round(3).tolist()
    pitch = round(math.degrees(float(pitch_of(T))), 3)
    outside = [
        j.name
        for j, v in zip(m.joints, q, strict=True)
        if not j.lower - 1e-9 <= v <= j.upper + 1e-9
    ]
    if args.json:
        joints = dict(zip(m.joint_names, args.angles, strict=True))
        print(
            json.dumps(
                {"arm": m.name, "joints_deg": joints, "position_mm": pos, "pitch_deg": pitch}
            )
        )
        return 0
    x, y, z = (fixed(v) for v in pos)
    print(f"position: x {x}  y {y}  z {z} mm   pitch {fixed(pitch)} deg")
    if outside:
        print(
            f"note: outside the joint limits: {', '.join(outside)} (see 'armkit --arm {args.arm} show')"
        )
    return 0


def run_ik(args: argparse.Namespace) -> int:
    import json

    import numpy as np

    from ..kinematics import ik
    from ..model import load_model

    m = load_model(args.arm)
    target = [float(args.x), float(args.y), float(args.z)]
    if not all(math.isfinite(v) for v in target):
        shown = ", ".join(f"{v:.6g}" for v in target)
        raise InputError(f"X Y Z must be finite numbers in mm, got {shown}")
    if args.pitch is not None and not (math.isfinite(args.pitch) and abs(args.pitch) <= 180.0):
        raise InputError(f"--pitch must be an angle from -180 to 180 deg, got {args.pitch:.6g}")
    pitch = None if args.pitch is None else math.radians(args.pitch)
    result = ik(m, np.array(target) / 1000.0, pitch, method=args.method)
    sols = result.solutions if args.all else result.solutions[:1]
    degs = [np.degrees(s).round(3).tolist() for s in sols]
    if args.json:
        out: dict[str, Any] = {"arm": m.name, "target_mm": target, "pitch_deg": args.pitch}
        out["solutions"] = [{"joints_deg": dict(zip(m.joint_names, d, strict=True))} for d in degs]
        out["method"], out["iterations"] = result.method, result.iterations
        print(json.dumps(out))
        return 0
    rows = [[k + 1, *d] for k, d in enumerate(degs)]
    print(table(["#", *(f"{n} deg" for n in m.joint_names)], rows))
    if not args.all and len(result.solutions) > 1:
        print(f"({count(len(result.solutions), 'solution')}; --all shows every one)")
    if result.method != "analytic":
        print(
            f"({result.method}: {count(result.iterations, 'iteration')}, {count(result.restarts, 'restart')}, "
            f"off by {result.position_error * 1000:.4f} mm)"
        )
    return 0


def run_plot(args: argparse.Namespace) -> int:
    from ..model import load_model

    m = load_model(args.arm)
    q = joint_angles(m, args.angles)
    check_output_path(args.output, "-o/--output", IMAGE_SUFFIXES)
    from ..viz import plot_pose

    path = plot_pose(m, q, args.output)
    print(f"wrote {path}")
    return 0
