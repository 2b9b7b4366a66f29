"""``armkit demo``: a short tour on the simulated OpenManipulator-X."""

from __future__ import annotations

import argparse
import math
from pathlib import Path
from typing import Any

import numpy as np

from .._errors import UnreachableError
from ..kinematics import fk, ik, pitch_of
from ..model import load_model
from ._args import check_output
from ._table import table

NEXT = ("armkit --help", "armkit --arm lynx6 ik 200 0 50 --pitch -45 --all", "armkit arms")

TOUR = [  # (x, y, z) mm, pitch deg: above a cube, a cube to the left, reaching far, too far
    ((200.0, 0.0, 50.0), -90.0),
    ((150.0, 120.0, 30.0), -90.0),
    ((280.0, -40.0, 120.0), 0.0),
    ((180.0, 0.0, 250.0), 30.0),
    ((450.0, 0.0, 50.0), -90.0),
]


def add_commands(sub: argparse._SubParsersAction[Any]) -> None:
    """Add ``demo``."""
    p = sub.add_parser(
        "demo",
        help="a short tour on the simulated OpenManipulator-X (no hardware)",
        description="Solve a few gripper targets on the simulated OpenManipulator-X, check each "
        "answer by forward kinematics, and draw the first pose.",
    )
    p.add_argument(
        "-o",
        "--output",
        default="demo_pose.png",
        metavar="FILE",
        help="picture (default demo_pose.png)",
    )
    p.set_defaults(func=run_demo)


def run_demo(args: argparse.Namespace) -> int:
    check_output(args.output, "-o/--output", image=True)
    m = load_model("openmanipulator_x")
    print(f"armkit demo: {m.description}\n")
    print(
        "Where should the gripper go?  armkit finds the joint angles and checks them by forward kinematics.\n"
    )
    rows, first = [], None
    for xyz, pitch in TOUR:
        try:
            res = ik(m, np.array(xyz) / 1000.0, math.radians(pitch))
        except UnreachableError as exc:
            rows.append([*_fmt(xyz), pitch, f"unreachable ({exc.reason})", "", ""])
            continue
        first = res.q if first is None else first
        T = fk(m, res.q)
        err = float(np.linalg.norm(T[:3, 3] * 1000 - xyz))
        angles = " ".join(f"{v:7.2f}" for v in np.degrees(res.q))
        rows.append(
            [*_fmt(xyz), pitch, angles, f"{err:.1e}", round(math.degrees(float(pitch_of(T))), 2)]
        )
    headers = [
        "x mm",
        "y mm",
        "z mm",
        "pitch",
        "waist shoulder elbow wrist (deg)",
        "error mm",
        "fk pitch",
    ]
    print(table(headers, rows))
    _draw_circle(m)
    _picture(m, first, args.output)
    print("\nNext: " + ", ".join(f"'{command}'" for command in NEXT) + ".")
    return 0


def _draw_circle(m: Any) -> None:
    """Draw a 40 mm circle with the simulated arm and measure the pen's true path."""
    from ..arm import Arm
    from ..motion import TimedStreaming, circle, distance_to_polyline

    print(
        "\nNow the simulated arm draws a 40 mm circle, pen pointing down (timed streaming, 100 Hz):"
    )
    with Arm(m, driver="sim") as arm:  # in memory: the demo leaves no state behind
        world = arm.world
        assert world is not None  # driver="sim" is simulated
        points = circle(np.array([0.17, 0.0, 0.05]), 0.04, spacing=0.002) * 1000
        x, y, z = points[0]
        arm.move_to(x, y, z, -90.0)
        start = arm.clock.now()
        arm.follow(points, -90.0, streamer=TimedStreaming(rate=100.0, speed=0.06))
        took = arm.clock.now() - start
        record = world.recording().between(start, arm.clock.now())
        error = distance_to_polyline(fk(m, record.q)[:, :3, 3] * 1000, points)
    print(
        f"  {len(points)} waypoints in {took:.2f} s (the real Dynamixel driver on simulated XM430s with lag); the pen's true path is "
        f"{np.sqrt(np.mean(error**2)):.3f} mm RMS, {error.max():.3f} mm at worst from the circle"
    )


def _fmt(xyz: tuple[float, float, float]) -> list[object]:
    return [round(v, 1) for v in xyz]


def _picture(m: Any, q: Any, output: str) -> None:
    if q is None:
        return
    try:
        from ..viz import plot_pose

        path = plot_pose(m, q, Path(output), title="armkit demo: above a cube, pitch -90 deg")
    except Exception as exc:  # a missing plot extra must not spoil the tour
        print(f"\n(no picture: {exc})")
        return
    print(f"\npicture of the first pose: {path}")
