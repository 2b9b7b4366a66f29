"""``armkit arms`` and ``armkit show``: what the shipped and user models are."""

from __future__ import annotations

import argparse
import math
from typing import TYPE_CHECKING, Any

from ._table import table

if TYPE_CHECKING:
    from ..model import ArmModel


def add_commands(sub: argparse._SubParsersAction[Any]) -> None:
    """Add ``arms`` and ``show``."""
    p = sub.add_parser(
        "arms", help="list the shipped arm models", description="List the shipped arm models."
    )
    p.set_defaults(func=run_arms)
    p = sub.add_parser(
        "show",
        help="joints, limits, home and DH table of --arm",
        description="Show the arm's joints (limits and home in degrees), its DH table (mm, deg), tool and gripper.",
    )
    p.set_defaults(func=run_show)


def run_arms(args: argparse.Namespace) -> int:
    from ..kinematics import closed_form
    from ..model import load_model, shipped_models

    rows = []
    for name in shipped_models():
        m = load_model(name)
        closed = "closed form" if closed_form(m) else "numeric"
        rows.append([name, m.dof, ", ".join(m.joint_names), closed, m.description])
    print(table(["arm", "dof", "joints", "ik", "description"], rows))
    return 0


def run_show(args: argparse.Namespace) -> int:
    from ..kinematics import closed_form
    from ..model import load_model

    m = load_model(args.arm)
    print(f"{m.name}: {m.description}")
    print(f"model file: {m.source}")
    print()
    print(
        table(
            ["joint", "min deg", "max deg", "home deg", "max deg/s"],
            [_joint_row(j) for j in m.joints],
        )
    )
    print()
    if m.convention == "frames":  # a URDF model: joint frames, no DH rows
        print(f"chain: {m.dof} joint frames (origin and axis per joint, as URDF gives them)")
    else:
        print(
            f"DH convention: {m.convention}"
            + (" (Craig: alpha, a of row i-1)" if m.convention == "modified" else "")
        )
        print(
            table(["joint", "a mm", "alpha deg", "d mm", "theta offset deg", "sign"], _dh_rows(m))
        )
    print()
    print(_tool_line(m))
    g = m.gripper
    if g.present:
        print(f"gripper: {g.kind}, opening {g.width_min * 1000:.1f}..{g.width_max * 1000:.1f} mm")
    else:
        print("gripper: none (the model gives no [gripper] width_mm range)")
    pitch = "free" if m.default_pitch is None else f"{math.degrees(m.default_pitch):.1f} deg"
    family = f"closed form ({closed_form(m)})" if closed_form(m) else "numeric"
    print(f"pitch when none is given: {pitch}; inverse kinematics: {family}")
    return 0


def _joint_row(j: Any) -> list[object]:
    return [j.name, *(math.degrees(v) for v in (j.lower, j.upper, j.home, j.max_velocity))]


def _dh_rows(m: ArmModel) -> list[list[object]]:
    return [
        [
            j.name,
            r.a * 1000,
            math.degrees(r.alpha),
            r.d * 1000,
            math.degrees(r.theta_offset),
            "-q" if r.sign < 0 else "+q",
        ]
        for j, r in zip(m.joints, m.dh, strict=True)
    ]


def _tool_line(m: ArmModel) -> str:
    x, y, z = (m.T_flange_tool[:3, 3] * 1000).round(2).tolist()
    frame = "joint's" if m.convention == "frames" else "DH"
    return f"tool: ({x}, {y}, {z}) mm from the last {frame} frame; its x axis is the approach direction"
