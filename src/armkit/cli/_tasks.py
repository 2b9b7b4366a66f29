"""Task commands on a scene: pick, place, move-item, rotate-cube, stack (mm, deg).

Each task is planned whole before anything moves; ``--dry-run`` prints the plan.
"""

from __future__ import annotations

import argparse
import math
from typing import Any

from .._errors import ArmkitError, InputError

EPILOG = (
    "Needs --scene FILE|NAME before the command (see 'armkit scene list'). The whole task "
    "is planned first (every point solved, every move checked against the table and the "
    "scene); a step that cannot be done is named and nothing moves. Positions in mm, "
    "angles in degrees. TO is a place, board[ROW,COL], a cube to stack on or a container."
)


def add_commands(sub: argparse._SubParsersAction[Any]) -> None:
    """Add pick, place, move-item, rotate-cube and stack."""
    p = _task(sub, "pick", "pick a cube up (001: from the top where reachable, else the side)")
    p.add_argument("cube", help="the cube's name in the scene")
    _pitch(p)
    p = _task(sub, "place", "put the held cube (picked by 'pick') down at TO")
    p.add_argument("cube", help="the cube in the gripper")
    _target(p)
    _pitch(p)
    p = _task(sub, "move-item", "000's moveItem: pick a cube up, lift, carry it to TO, put it down")
    p.add_argument("cube", help="the cube's name in the scene")
    _target(p)
    p.add_argument(
        "--lift",
        type=float,
        default=40.0,
        metavar="MM",
        help="lift before travelling [mm] (default 40)",
    )
    _pitch(p)
    p = _task(sub, "rotate-cube", "001: turn a cube a quarter turn in place")
    p.add_argument("cube", help="the cube's name in the scene")
    p.add_argument(
        "--backward",
        action="store_true",
        help="pick from the top, put down from the side (default: forward, the other way)",
    )
    p = _task(sub, "stack", "001: turn every cube in place, then stack them on the first")
    p.add_argument(
        "cubes", nargs="+", metavar="CUBE", help="two or more cubes, the first stays below"
    )
    p.add_argument("--rotate", choices=("forward", "backward", "none"), default="forward", help="how to turn them first (default forward)")  # fmt: skip


def _task(sub: argparse._SubParsersAction[Any], name: str, text: str) -> argparse.ArgumentParser:
    p: argparse.ArgumentParser = sub.add_parser(
        name, help=text, description=text + ".", epilog=EPILOG
    )
    p.add_argument("--dry-run", action="store_true", help="print the plan, move nothing")
    p.add_argument(
        "--clearance",
        type=float,
        default=30.0,
        metavar="MM",
        help="first waypoint above each grasp [mm] (>= 30, default 30)",
    )
    p.add_argument("--calibration", metavar="FILE", help="the unit's offsets (height_offset_mm, perpendicular_offset_mm); default <config>/<arm>_tasks.toml if present")  # fmt: skip
    p.set_defaults(func=_run)
    return p


def _pitch(p: argparse.ArgumentParser) -> None:
    p.add_argument("--pitch", type=float, metavar="DEG", help="gripper pitch [deg] (-90 from the top, 0 from the side; default: 001's choice)")  # fmt: skip


def _target(p: argparse.ArgumentParser) -> None:
    p.add_argument(
        "to", nargs="?", metavar="TO", help="a place, board[ROW,COL], a cube or a container"
    )
    p.add_argument("--xyz", nargs=3, type=float, metavar=("X", "Y", "Z"), help="or a point for the cube's bottom [mm]")  # fmt: skip


def _run(args: argparse.Namespace) -> int:
    from .. import tasks
    from ._scene import scene_of

    scene = scene_of(args)
    options = {"clearance": args.clearance, "calibration": args.calibration, "dry_run": True}
    with _open_arm(args, scene) as arm:
        plan = _plan(args, tasks, arm, scene, options)
        if args.dry_run:
            print(plan)
            return 0
        print(plan.lines()[0])
        tasks.run_plan(
            arm, plan, say=lambda k, step: print(f"{k:4d}/{len(plan.steps)}  {step.label}")
        )
        for line in plan.lines()[len(plan.steps) + 1 :]:
            print(line)
    return 0


def _plan(
    args: argparse.Namespace, tasks: Any, arm: Any, scene: Any, options: dict[str, Any]
) -> Any:
    if args.command == "pick":
        return tasks.pick(arm, scene, args.cube, pitch=args.pitch, **options)
    if args.command == "rotate-cube":
        direction = "backward" if args.backward else "forward"
        return tasks.rotate_cube(arm, scene, args.cube, direction, **options)
    if args.command == "stack":
        rotate = None if args.rotate == "none" else args.rotate
        return tasks.stack(arm, scene, args.cubes, rotate_first=rotate, **options)
    to = _to(args)
    if args.command == "place":
        return tasks.place(arm, scene, args.cube, to, pitch=args.pitch, **options)
    if not (math.isfinite(args.lift) and 0 <= args.lift <= 500):
        raise InputError(f"--lift must be 0..500 mm, got {args.lift}")
    return tasks.move_item(arm, scene, args.cube, to, lift=args.lift, pitch=args.pitch, **options)


def _to(args: argparse.Namespace) -> Any:
    if (args.to is None) == (args.xyz is None):
        raise ArmkitError(f"'{args.command}' needs TO (a place, board[ROW,COL], cube or container) or --xyz X Y Z [mm], not both")  # fmt: skip
    return args.to if args.to is not None else tuple(args.xyz)


def _open_arm(args: argparse.Namespace, scene: Any) -> Any:
    """The Arm of --arm/--driver/--port with the scene; the simulated servo arm keeps
    its joints between runs in its state file, as for 'move'."""
    from ..arm import Arm
    from ..connect import open_driver
    from ..model import load_model

    model = load_model(args.arm)
    return Arm(model, open_driver(model, args.driver, args.port, keep=True), scene=scene)
