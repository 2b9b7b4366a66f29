"""Motion commands: move, joints, grip, home, where, draw (millimetres, degrees); the
shapes of ``draw`` are ``armkit.cli._draw_shapes``'s.

With ``--driver sim`` the simulated arm's true joint angles and grip are kept
between invocations in a state file, so ``move`` then ``where`` agree:
``$ARMKIT_CONFIG_DIR/sim_<arm>.json`` (a model file of your own:
``sim_<arm>-<hash of its path>.json``), else ``$XDG_CONFIG_HOME/armkit/`` or
``~/.config/armkit/``. ``--port FILE`` uses another file; delete it to start at home.
"""

from __future__ import annotations

import argparse
from typing import TYPE_CHECKING, Any

from .._terminal import fixed
from ..model import MAX_MOVE_S
from ._args import angle, coordinate, number, percent
from ._draw_shapes import MODES as MODES
from ._draw_shapes import add_draw
from ._open_arm import open_arm
from ._watch import add_watch_options

if TYPE_CHECKING:
    from ..arm import MAX_MOVE_S, Arm

SIM_NOTE = (
    "With --driver sim, the simulated arm's joint angles are kept between runs in "
    "$ARMKIT_CONFIG_DIR/sim_<arm>.json (default ~/.config/armkit/); delete it to start at home; "
    "a second process on the same simulated arm is refused until the first ends."
)


def add_commands(sub: argparse._SubParsersAction[Any]) -> None:
    """Add move, joints, grip, home, where and draw."""
    p = sub.add_parser("move", help="move the gripper point to X Y Z [mm]", epilog=SIM_NOTE)
    for axis in "xyz":
        p.add_argument(axis, type=coordinate, metavar=axis.upper(), help=f"target {axis} [mm]")
    p.add_argument(
        "--pitch",
        type=angle,
        metavar="DEG",
        help="gripper pitch [deg] (0 level, -90 down); default: the arm's own where its model "
        "has one (owi535: 0), else the pitch nearest the gripper's now that reaches X Y Z",
    )
    _timing_options(p)
    add_watch_options(p)
    p.set_defaults(func=_move)
    p = sub.add_parser("joints", help="move every joint to the given angles [deg]", epilog=SIM_NOTE)
    p.add_argument("angles", nargs="+", type=angle, metavar="DEG", help="one angle per joint [deg]")
    _timing_options(p)
    add_watch_options(p)
    p.set_defaults(func=_joints)
    p = sub.add_parser("grip", help="open the gripper to WIDTH [mm]", epilog=SIM_NOTE)
    p.add_argument("width", type=number("mm", 0.0, 1000.0), metavar="WIDTH_MM", help="opening [mm]")
    add_watch_options(p)
    p.set_defaults(func=_grip)
    p = sub.add_parser("home", help="move every joint to its home angle", epilog=SIM_NOTE)
    add_watch_options(p)
    p.set_defaults(func=_home)
    p = sub.add_parser("where", help="print the gripper position and joint angles", epilog=SIM_NOTE)
    p.set_defaults(func=_where)
    add_draw(sub)


def _timing_options(p: argparse.ArgumentParser) -> None:
    p.add_argument(
        "--speed",
        type=percent(0.0, 100.0, low_open=True),
        metavar="PERCENT",
        help="percent of each joint's top speed, > 0 and <= 100 %% (default 100: full speed), "
        "as a script's 'speed 50%%'",
    )
    p.add_argument(
        "--duration",
        type=number("s", 0.0, MAX_MOVE_S),
        metavar="S",
        help=f"time for the move [s], at most {MAX_MOVE_S:g} (default: as fast as --speed allows)",
    )


def _move(args: argparse.Namespace) -> int:
    with open_arm(args) as arm:
        speed = None if args.speed is None else args.speed / 100.0  # [%] -> the fraction Arm takes
        arm.move_to(args.x, args.y, args.z, args.pitch, speed=speed, duration=args.duration)
        _print_where(arm, args)
    return 0


def _joints(args: argparse.Namespace) -> int:
    with open_arm(args) as arm:
        speed = None if args.speed is None else args.speed / 100.0  # [%] -> the fraction Arm takes
        arm.move_joints(args.angles, speed=speed, duration=args.duration)
        _print_where(arm, args)
    return 0


def _grip(args: argparse.Namespace) -> int:
    with open_arm(args) as arm:
        arm.grip(args.width)
        closed = args.width <= arm.model.gripper.width_min * 1000.0 + 1e-9
        print("gripper closed" if closed else f"gripper open {args.width:.1f} mm")
    return 0


def _home(args: argparse.Namespace) -> int:
    with open_arm(args) as arm:
        arm.home()
        _print_where(arm, args)
    return 0


def _where(args: argparse.Namespace) -> int:
    with open_arm(args) as arm:
        _print_where(arm, args)
    return 0


def _print_where(arm: Arm, args: argparse.Namespace) -> None:
    x, y, z, pitch = (round(v, 1) + 0.0 for v in arm.position())  # + 0.0: no "-0.0"
    print(f"gripper at x {x:.1f} y {y:.1f} z {z:.1f} mm, pitch {pitch:.1f} deg")
    angles = "  ".join(f"{n} {fixed(a)}" for n, a in arm.angles().items())
    print(f"joints {angles} deg")
    reason = arm.uncertainty
    if reason:
        print(
            f"uncertain: these are estimates ({reason}); to know the angles again run "
            f"'armkit --arm {args.arm} --driver {args.driver_name} rehome'"
        )
