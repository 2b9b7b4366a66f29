"""Task commands on a scene: pick, place, move-item, rotate-cube, stack (mm, deg).

Each task is planned whole before anything moves; ``--dry-run`` prints the plan.
"""

from __future__ import annotations

import argparse
import math
import sys
from typing import Any

from .._errors import ArmkitError, InputError
from ._watch import add_watch_options, watched_arm

EPILOG = (
    "Needs --scene FILE|NAME before the command (see 'armkit scene list'). The whole task "
    "is planned first (every point solved, every move checked against the table and the "
    "scene); a step that cannot be done is named and nothing moves. Positions in mm, "
    "angles in degrees."
)
TO_HELP = " TO is a place, board[ROW,COL], a cube to stack on or a container."


SEARCH_EPILOG = (
    "Needs --scene (shipped: search_002, reach_003). The distance sensor (a Sharp GP2D120 on the "
    "hand, 4..30 cm) is read through the SSC-32's VA..VD on a Lynx6, else a serial ADC "
    "board (emulated on a pty in the simulator). Angles in degrees, distances in mm. Exit "
    "status: 0 {found}; 1 {none} (one line on stderr says what was scanned and what to "
    "try); 2 a mistake or a step that cannot be done (one line, 'armkit: error: ...')."
)
REACH_ARC = (30.0, 120.0, 5.0)  # [deg] reach's scan: from, to, step (002's base servo angles)
NEAR, FAR = "4", "30 cm"  # the sensor's range (armkit.sensing.RANGE), as a result says it


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
    _search_command(sub)


def _search_command(sub: argparse._SubParsersAction[Any]) -> None:
    text = "002: scan with the distance sensor, pick up what it finds, drop it in a container"
    angles = " Scan angles are the base servo's, as in 002: 90 deg is straight ahead."
    p: argparse.ArgumentParser = sub.add_parser(
        "search", help=text, description=text + "." + angles,
        epilog=SEARCH_EPILOG.format(found="found, picked up and dropped", none="nothing found"),
    )  # fmt: skip
    for flag, default, what in (("--from", 30.0, "first"), ("--to", 120.0, "last"), ("--step", 5.0, "coarse step of the")):  # fmt: skip
        p.add_argument(flag, dest=flag[2:], type=float, default=default, metavar="DEG", help=f"{what} scan angle [deg] (default {default:g})")  # fmt: skip
    p.add_argument("--into", metavar="NAME", help="the container to drop it in (default: the scene's only one)")  # fmt: skip
    p.add_argument("--adc-port", metavar="PORT", help="the serial ADC board the sensor is wired to (arms without an SSC-32, real hardware; default: none, the SSC-32's own inputs or the simulator's)")  # fmt: skip
    p.add_argument("--channel", type=int, default=0, choices=range(4), help="the sensor's analog input, 0..3 (SSC-32 VA..VD; default 0)")  # fmt: skip
    add_watch_options(p)
    p.set_defaults(func=_search)
    text = "003: find a hand held out with the distance sensor, come near it and shake it"
    scans = f" It scans the base {_arc(*REACH_ARC)}."
    epilog = SEARCH_EPILOG.format(found="the hand found, come near and shaken", none="no hand found")  # fmt: skip
    p = sub.add_parser("reach", help=text, description=text + "." + scans, epilog=epilog)
    p.add_argument("--height", type=float, default=110.0, metavar="MM", help="height of the scan, the hand's [mm] (default 110)")  # fmt: skip
    p.add_argument("--near", type=float, default=60.0, metavar="MM", help="stop when the sensor reads this [mm], 40..300 (default 60)")  # fmt: skip
    p.add_argument("--shakes", type=int, default=3, metavar="N", help="up-and-down shakes, 0..20 (default 3)")  # fmt: skip
    p.add_argument("--adc-port", metavar="PORT", help="the serial ADC board the sensor is wired to (arms without an SSC-32, real hardware; default: none, the SSC-32's own inputs or the simulator's)")  # fmt: skip
    p.add_argument("--channel", type=int, default=0, choices=range(4), help="the sensor's analog input, 0..3 (default 0)")  # fmt: skip
    add_watch_options(p)
    p.set_defaults(func=_reach)


def _reach(args: argparse.Namespace) -> int:
    from .. import tasks
    from ._scene import scene_of

    scene = scene_of(args)
    if not math.isfinite(args.height) or not 0.0 < args.height <= 500.0:
        raise InputError(f"--height must be 0..500 mm, got {args.height}")
    start, stop, step = REACH_ARC
    with watched_arm(args, scene) as arm:
        result = tasks.reach(
            arm, scene, height=args.height, near=args.near,
            shakes=args.shakes, start=start, stop=stop, step=step, channel=args.channel,
            port=args.adc_port,
        )  # fmt: skip
        if not result.found:
            todo = f"hold the hand out on that arc within {FAR} of the sensor, or give --height the hand's height"  # fmt: skip
            return _nothing(args, arm, result, f"no hand found: scanned {_arc(*REACH_ARC)} at {args.height:g} mm height", todo)  # fmt: skip
        print("\n".join(result.lines()))
    return 0


def _search(args: argparse.Namespace) -> int:
    from .. import tasks
    from ._scene import scene_of

    scene = scene_of(args)
    angles = {k: getattr(args, k) for k in ("from", "to", "step")}
    with watched_arm(args, scene) as arm:
        result = tasks.search(
            arm, scene, start=angles["from"], stop=angles["to"], step=angles["step"],
            into=args.into, channel=args.channel, port=args.adc_port,
        )  # fmt: skip
        if not result.found:
            arc = _arc(getattr(args, "from"), args.to, args.step)
            near, far = (round(b * 1000) for b in result.band)
            todo = (
                f"widen --from/--to (0..180), lower --step, or put the object {near}..{far} mm "
                f"from the base on that arc (nearer than {near} mm it is inside the sensor's "
                f"{NEAR} cm minimum)"
            )
            return _nothing(args, arm, result, f"nothing found: scanned {arc}", todo)
        print("\n".join(result.lines()))
    return 0


def _arc(start: float, stop: float, step: float) -> str:
    """A scan's arc as its options are written: 'from 100 to 120 deg every 5 deg (...)'."""
    return f"from {start:g} to {stop:g} deg every {step:g} deg (90 is straight ahead)"


def _nothing(args: argparse.Namespace, arm: Any, result: Any, scanned: str, todo: str) -> int:
    """A scan that found nothing: the task's lines but its last (its own 'nothing
    within 30 cm'), then one line on stderr: what was scanned, what to try; status 1."""

    print("\n".join(result.lines()[:-1]))
    sys.stdout.flush()  # the result, then the line that ends it
    said = f"armkit: {scanned}, the sensor seeing {NEAR}..{FAR}; {todo}"
    if arm.moves == "timed":  # the OWI scanned where it thinks it was
        said += (
            f"; the {arm.model.name}'s angles are only estimated from motor run times: re-home "
            f"it and scan again: armkit --arm {args.arm} --driver {args.driver_name} rehome"
        )
    print(said, file=sys.stderr)
    return 1


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
    add_watch_options(p)
    p.set_defaults(func=_run)
    return p


def _pitch(p: argparse.ArgumentParser) -> None:
    p.add_argument("--pitch", type=float, metavar="DEG", help="gripper pitch [deg] (-90 from the top, 0 from the side; default: 001's choice)")  # fmt: skip


def _target(p: argparse.ArgumentParser) -> None:
    p.epilog = (p.epilog or "") + TO_HELP
    p.add_argument(
        "to", nargs="?", metavar="TO", help="a place, board[ROW,COL], a cube or a container"
    )
    p.add_argument("--xyz", nargs=3, type=float, metavar=("X", "Y", "Z"), help="or a point for the cube's bottom [mm] (default: none, TO names where)")  # fmt: skip


def _run(args: argparse.Namespace) -> int:
    from .. import tasks
    from ._scene import scene_of

    scene = scene_of(args)
    options = {"clearance": args.clearance, "calibration": args.calibration, "dry_run": True}
    with watched_arm(args, scene) as arm:
        plan = _plan(args, tasks, arm, scene, options)
        if args.dry_run:
            print(plan)
            return 0
        print(plan.lines()[0])
        tasks.run_verified(
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
    return tasks.move_item(arm, scene, args.cube, to, lift=args.lift, pitch=args.pitch, **options)


def _to(args: argparse.Namespace) -> Any:
    if (args.to is None) == (args.xyz is None):
        if args.to is not None:
            raise ArmkitError(f"'{args.command}' takes TO {args.to} or --xyz X Y Z [mm], not both; drop one")  # fmt: skip
        raise ArmkitError(f"'{args.command}' needs TO <where> (a place, board[ROW,COL], cube or container) or --xyz X Y Z [mm]")  # fmt: skip
    return args.to if args.to is not None else tuple(args.xyz)
