"""Motion commands: move, joints, grip, home, where, draw (millimetres, degrees).

With ``--driver sim`` the simulated arm's true joint angles and grip are kept
between invocations in a state file, so ``move`` then ``where`` agree:
``$ARMKIT_CONFIG_DIR/sim_<arm>.json`` (a model file of your own:
``sim_<arm>-<hash of its path>.json``), else ``$XDG_CONFIG_HOME/armkit/`` or
``~/.config/armkit/``. ``--port FILE`` uses another file; delete it to start at home.
"""

from __future__ import annotations

import argparse
import math
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ..arm import Arm
from ..connect import open_driver
from ..model import load_model
from ..motion import (
    EarlyStreaming,
    NaiveStepping,
    Streamer,
    TimedStreaming,
    arc,
    cube_edges,
    line,
    rectangle,
)

F64 = NDArray[np.float64]
MODES = ("naive", "early", "timed")
SIM_NOTE = (
    "With --driver sim, the simulated arm's joint angles are kept between runs in "
    "$ARMKIT_CONFIG_DIR/sim_<arm>.json (default ~/.config/armkit/); delete it to start at home; "
    "a second process on the same simulated arm is refused until the first ends."
)


def add_commands(sub: argparse._SubParsersAction[Any]) -> None:
    """Add move, joints, grip, home, where and draw."""
    p = sub.add_parser("move", help="move the gripper point to X Y Z [mm]", epilog=SIM_NOTE)
    p.add_argument("xyz", nargs=3, type=float, metavar=("X", "Y", "Z"), help="target [mm]")
    p.add_argument("--pitch", type=float, help="gripper pitch [deg] (0 level, -90 down)")
    _timing_options(p)
    p.set_defaults(func=_move)
    p = sub.add_parser("joints", help="move every joint to the given angles [deg]", epilog=SIM_NOTE)
    p.add_argument("angles", nargs="+", type=float, metavar="DEG", help="one angle per joint [deg]")
    _timing_options(p)
    p.set_defaults(func=_joints)
    p = sub.add_parser("grip", help="open the gripper to WIDTH [mm]", epilog=SIM_NOTE)
    p.add_argument("width", type=float, metavar="WIDTH_MM", help="opening [mm]")
    p.set_defaults(func=_grip)
    p = sub.add_parser("home", help="move every joint to its home angle", epilog=SIM_NOTE)
    p.set_defaults(func=_home)
    p = sub.add_parser("where", help="print the gripper position and joint angles", epilog=SIM_NOTE)
    p.set_defaults(func=_where)
    _add_draw(sub)


def _timing_options(p: argparse.ArgumentParser) -> None:
    p.add_argument("--speed", type=float, help="fraction of each joint's max speed, (0, 1]")
    p.add_argument("--duration", type=float, metavar="S", help="time for the move [s]")


def _add_draw(sub: argparse._SubParsersAction[Any]) -> None:
    draw = sub.add_parser("draw", help="draw a circle, line, rectangle or cube with the gripper")
    shapes = draw.add_subparsers(dest="shape", metavar="SHAPE", required=True)
    p = shapes.add_parser("circle", help="circle (or arc) in the horizontal plane")
    p.add_argument(
        "--center", nargs=3, type=float, required=True, metavar=("X", "Y", "Z"), help="[mm]"
    )
    p.add_argument("--radius", type=float, required=True, metavar="MM", help="[mm]")
    p.add_argument("--start", type=float, default=0.0, metavar="DEG", help="start angle (0 = +x)")
    p.add_argument("--sweep", type=float, default=360.0, metavar="DEG", help="sweep (default 360)")
    _draw_options(p)
    p = shapes.add_parser("line", help="straight line from X1 Y1 Z1 to X2 Y2 Z2 [mm]")
    p.add_argument("ends", nargs=6, type=float, metavar=("X1", "Y1", "Z1", "X2", "Y2", "Z2"))
    _draw_options(p)
    p = shapes.add_parser("rect", help="rectangle in the horizontal plane")
    p.add_argument(
        "--center", nargs=3, type=float, required=True, metavar=("X", "Y", "Z"), help="[mm]"
    )
    p.add_argument("--size", nargs=2, type=float, required=True, metavar=("W", "D"), help="[mm]")
    _draw_options(p)
    p = shapes.add_parser("cube", help="every edge of a cube in one stroke (seed 001)")
    p.add_argument(
        "--corner", nargs=3, type=float, required=True, metavar=("X", "Y", "Z"), help="lowest [mm]"
    )
    p.add_argument("--size", type=float, required=True, metavar="MM", help="edge [mm]")
    _draw_options(p)


def _draw_options(p: argparse.ArgumentParser) -> None:
    p.add_argument("--pitch", type=float, help="gripper pitch [deg] (0 level, -90 down)")
    p.add_argument("--mode", choices=MODES, default="timed", help="how waypoints are sent")
    p.add_argument("--spacing", type=float, default=2.0, metavar="MM", help="between waypoints")
    p.add_argument("--speed", type=float, default=50.0, metavar="MM_S", help="tool speed (timed)")
    p.add_argument("--fraction", type=float, default=0.5, help="early mode: send at this fraction")
    p.add_argument(
        "--record",
        metavar="FILE.csv",
        help="simulated arms only: write t_s,<joint>_deg,... one row per 1 ms of simulated time",
    )
    p.set_defaults(func=_draw)


def _open(args: argparse.Namespace) -> Arm:
    model = load_model(args.arm)
    return Arm(model, open_driver(model, args.driver, args.port, keep=True))


def _move(args: argparse.Namespace) -> int:
    with _open(args) as arm:
        x, y, z = args.xyz
        arm.move_to(x, y, z, args.pitch, speed=args.speed, duration=args.duration)
        _print_where(arm)
    return 0


def _joints(args: argparse.Namespace) -> int:
    with _open(args) as arm:
        arm.move_joints(args.angles, speed=args.speed, duration=args.duration)
        _print_where(arm)
    return 0


def _grip(args: argparse.Namespace) -> int:
    with _open(args) as arm:
        arm.grip(args.width)
        print(f"gripper open {args.width:.1f} mm")
    return 0


def _home(args: argparse.Namespace) -> int:
    with _open(args) as arm:
        arm.home()
        _print_where(arm)
    return 0


def _where(args: argparse.Namespace) -> int:
    with _open(args) as arm:
        _print_where(arm)
    return 0


def _print_where(arm: Arm) -> None:
    x, y, z, pitch = arm.position()
    print(f"gripper at x {x:.1f} y {y:.1f} z {z:.1f} mm, pitch {pitch:.1f} deg")
    print("joints " + "  ".join(f"{n} {a:.2f}" for n, a in arm.angles().items()) + " deg")


def _draw(args: argparse.Namespace) -> int:
    points = _shape_points(args)
    streamer = _streamer(args)
    if args.record and args.driver != "sim" and args.port != "emu":
        raise ValueError("--record needs a simulated arm (--driver sim, or --port emu)")
    with _open(args) as arm:
        t0 = arm.clock.now()
        arm.follow(points, args.pitch, streamer=streamer)
        took = arm.clock.now() - t0
        print(f"drew {args.shape}: {len(points)} points in {took:.2f} s ({args.mode} mode)")
        if args.record and arm.world is not None:
            rows = arm.world.recording().between(t0, arm.clock.now()).write_csv(args.record)
            print(f"recorded {rows} samples (1 ms apart) to {args.record}")
    return 0


def _shape_points(args: argparse.Namespace) -> F64:
    """The shape's points [mm], shape (N, 3)."""
    sp = args.spacing / 1000.0
    if args.shape == "circle":
        c = np.array(args.center) / 1000.0
        start, sweep = math.radians(args.start), math.radians(args.sweep)
        pts = arc(c, args.radius / 1000.0, start, sweep, sp)
    elif args.shape == "line":
        pts = line(np.array(args.ends[:3]) / 1000.0, np.array(args.ends[3:]) / 1000.0, sp)
    elif args.shape == "rect":
        c = np.array(args.center) / 1000.0
        pts = rectangle(c, args.size[0] / 1000.0, args.size[1] / 1000.0, sp)
    else:
        pts = cube_edges(np.array(args.corner) / 1000.0, args.size / 1000.0, sp)
    return pts * 1000.0


def _streamer(args: argparse.Namespace) -> Streamer:
    if args.mode == "naive":
        return NaiveStepping()
    if args.mode == "early":
        if not 0.0 < args.fraction <= 1.0:
            raise ValueError(f"--fraction must be in (0, 1], got {args.fraction}")
        return EarlyStreaming(fraction=args.fraction)
    if not args.speed > 0:
        raise ValueError(f"--speed must be > 0 mm/s, got {args.speed}")
    return TimedStreaming(speed=args.speed / 1000.0)
