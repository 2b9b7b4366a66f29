"""``armkit draw circle|line|rect|cube``: a shape drawn through waypoints [mm] sent
as ``--mode`` says (naive, early or timed at ``--speed`` [mm/s]); the files
(``draw svg``, ``draw gcode``) are ``armkit.cli._draw``'s."""

from __future__ import annotations

import argparse
import math
from typing import TYPE_CHECKING, Any

from .._errors import InputError
from .._files import check_output_path
from .._terminal import count
from ._args import (
    MAX_DRAW_S,
    MAX_POINTS,
    SIZE_MM,
    SWEEP_DEG,
    angle,
    coordinate,
    number,
)
from ._draw import add_file_commands, add_plane_option, in_plane
from ._watch import add_watch_options

if TYPE_CHECKING:
    import numpy as np
    from numpy.typing import NDArray

    F64 = NDArray[np.float64]
    from ..model import ArmModel
    from ..motion import (
        Streamer,
    )

MODES = ("naive", "early", "timed")


def add_draw(sub: argparse._SubParsersAction[Any]) -> None:
    draw = sub.add_parser(
        "draw", help="draw an SVG or G-code file with a pen, or a circle, line, rectangle or cube"
    )
    shapes = draw.add_subparsers(dest="shape", metavar="SHAPE", required=True)
    size = number("mm", 0.0, SIZE_MM, low_open=True)
    p = shapes.add_parser("circle", help="circle (or arc), horizontal or in the plane of --normal")
    _center_option(p)
    p.add_argument("--radius", type=size, required=True, metavar="MM", help="radius [mm]")
    p.add_argument(
        "--start",
        type=angle,
        default=0.0,
        metavar="DEG",
        help="angle of the first point [deg], 0 = +x, 90 = +y (default 0)",
    )
    p.add_argument(
        "--sweep",
        type=number("deg", -SWEEP_DEG, SWEEP_DEG, nonzero=True),
        default=360.0,
        metavar="DEG",
        help="sweep [deg] (default 360; negative = clockwise)",
    )
    add_plane_option(p)
    _draw_options(p)
    p = shapes.add_parser("line", help="straight line from X1 Y1 Z1 to X2 Y2 Z2 [mm]")
    for name in ("X1", "Y1", "Z1", "X2", "Y2", "Z2"):
        p.add_argument(name.lower(), type=coordinate, metavar=name, help=f"{name} [mm]")
    _draw_options(p)
    p = shapes.add_parser("rect", help="rectangle, horizontal or in the plane of --normal")
    _center_option(p)
    p.add_argument(
        "--size",
        nargs=2,
        type=size,
        required=True,
        metavar=("W", "D"),
        help="width (along x) and depth (along y) [mm]",
    )
    add_plane_option(p)
    _draw_options(p)
    p = shapes.add_parser("cube", help="every edge of a cube in one stroke (seed 001)")
    p.add_argument(
        "--corner",
        nargs=3,
        type=coordinate,
        required=True,
        metavar=("X", "Y", "Z"),
        help="the corner with the lowest x, y and z [mm]",
    )
    p.add_argument("--size", type=size, required=True, metavar="MM", help="edge length [mm]")
    _draw_options(p)
    add_file_commands(shapes)


def _center_option(p: argparse.ArgumentParser) -> None:
    p.add_argument(
        "--center",
        nargs=3,
        type=coordinate,
        required=True,
        metavar=("X", "Y", "Z"),
        help="centre [mm]",
    )


def _draw_options(p: argparse.ArgumentParser) -> None:
    p.add_argument(
        "--pitch",
        type=angle,
        metavar="DEG",
        help="gripper pitch [deg] (0 level, -90 down); default: the arm's own, else one"
        " pitch for the whole path, the nearest the first point's that fits",
    )
    p.add_argument(
        "--mode",
        choices=MODES,
        default="timed",
        help="how waypoints are sent: naive (each once the arm is at the last), early (the "
        "next at --fraction of the way to the last), timed (on a clock, the tool at --speed) "
        "(default timed)",
    )
    p.add_argument(
        "--spacing",
        type=number("mm", 0.1, 1000.0),
        default=2.0,
        metavar="MM",
        help="between waypoints [mm], 0.1..1000 (default 2)",
    )
    p.add_argument(
        "--speed",
        type=number("mm/s", 1.0, 1000.0),
        default=50.0,
        metavar="MM_S",
        help="tool speed [mm/s] (timed mode, default 50)",
    )
    p.add_argument(
        "--fraction",
        type=number("", 0.0, 1.0, low_open=True),
        default=0.5,
        help="early mode: send the next waypoint at this fraction of a move, (0, 1] (default 0.5)",
    )
    p.add_argument(
        "--record",
        metavar="FILE.csv",
        help="simulated arms only: write t_s,<joint>_deg,... one row per 1 ms of simulated "
        "time (default: no file)",
    )
    add_watch_options(p)
    p.set_defaults(func=_draw)


def _draw(args: argparse.Namespace) -> int:
    from ._open_arm import open_arm

    points = _shape_points(args)
    streamer = _streamer(args, points)
    if args.record:
        if args.driver_name != "sim" and args.port != "emu":
            raise InputError("--record needs a simulated arm (--driver sim, or --port emu)")
        check_output_path(args.record, "--record")
    with open_arm(args) as arm:
        t0 = arm.clock.now()
        path = arm.follow(points, args.pitch, streamer=streamer)
        took = arm.clock.now() - t0
        print(f"drew {args.shape}: {count(len(points), 'point')} in {took:.2f} s ({args.mode} mode)"
              f"{'' if args.pitch is not None else _pitches(arm.model, path.q)}")  # fmt: skip
        if args.record and arm.world is not None:
            rows = arm.world.recording().between(t0, arm.clock.now()).write_csv(args.record)
            print(f"recorded {count(rows, 'sample')} (1 ms apart) to {args.record}")
    return 0


def _pitches(model: ArmModel, q: F64) -> str:
    """The pitch the solver chose along a path q (N, dof) [rad], as ', pitch P deg' or a
    range (planar2: the pitch follows from the position)."""
    import numpy as np

    from ..kinematics import fk, pitch_of

    pitches = np.degrees(pitch_of(fk(model, q)))
    lo, hi = float(pitches.min()), float(pitches.max())
    return f", pitch {lo:.1f} deg" if hi - lo < 0.05 else f", pitch {lo:.1f}..{hi:.1f} deg"


def _shape_length(args: argparse.Namespace) -> float:
    """Length of the shape's path [mm], known before a point is made."""
    import numpy as np

    if args.shape == "circle":
        return abs(math.radians(args.sweep)) * float(args.radius)
    if args.shape == "line":
        ends = np.array([args.x1, args.y1, args.z1, args.x2, args.y2, args.z2])
        return float(np.linalg.norm(ends[3:] - ends[:3]))
    if args.shape == "rect":
        return 2.0 * (float(args.size[0]) + float(args.size[1]))
    return 16.0 * float(args.size)  # the cube trace retraces three of its twelve edges


def _shape_points(args: argparse.Namespace) -> F64:
    """The shape's points [mm], shape (N, 3); InputError if there would be too many."""
    import numpy as np

    from ..motion import arc, cube_edges, line, rectangle

    count = _shape_length(args) / args.spacing
    if count > MAX_POINTS:
        raise InputError(
            f"--spacing {args.spacing:g} mm makes {count:.0f} waypoints for this "
            f"{_shape_length(args):.0f} mm {args.shape}; at most {MAX_POINTS}: "
            "use a larger --spacing or a smaller shape"
        )
    sp = args.spacing / 1000.0
    if args.shape == "circle":
        c = np.array(args.center) / 1000.0
        start, sweep = math.radians(args.start), math.radians(args.sweep)
        pts = in_plane(arc(c, args.radius / 1000.0, start, sweep, sp), c, args.normal)
    elif args.shape == "line":
        a = np.array([args.x1, args.y1, args.z1]) / 1000.0
        pts = line(a, np.array([args.x2, args.y2, args.z2]) / 1000.0, sp)
    elif args.shape == "rect":
        c = np.array(args.center) / 1000.0
        pts = in_plane(
            rectangle(c, args.size[0] / 1000.0, args.size[1] / 1000.0, sp), c, args.normal
        )
    else:
        pts = cube_edges(np.array(args.corner) / 1000.0, args.size / 1000.0, sp)
    return pts * 1000.0


def _streamer(args: argparse.Namespace, points: F64) -> Streamer:
    import numpy as np

    from ..motion import EarlyStreaming, NaiveStepping, TimedStreaming

    if args.mode == "naive":
        return NaiveStepping()
    if args.mode == "early":
        return EarlyStreaming(fraction=args.fraction)
    length = float(np.sum(np.linalg.norm(np.diff(points, axis=0), axis=1)))
    if length / args.speed > MAX_DRAW_S:
        raise InputError(
            f"drawing {length:.0f} mm at --speed {args.speed:g} mm/s would take "
            f"{length / args.speed:.0f} s; at most {MAX_DRAW_S:g} s: raise --speed"
        )
    return TimedStreaming(speed=args.speed / 1000.0)
