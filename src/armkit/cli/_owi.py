"""OWI-535 commands: keys (keyboard mode), pick-place, rehome, light."""

from __future__ import annotations

import argparse
import sys
from typing import TYPE_CHECKING, Any

from .._closing import closing
from .._errors import ArmkitError
from .._files import config_dir
from ._args import check_folder, coordinate, number

if TYPE_CHECKING:
    from ..drivers.timed import TimedDriver


def add_commands(sub: argparse._SubParsersAction[Any]) -> None:
    """Add ``keys``, ``pick-place``, ``rehome`` and ``light``."""
    p = sub.add_parser(
        "keys",
        help="OWI-535: drive the joints from the keyboard, one key = one 250 ms move",
        description="000's letters: w/s gripper close/open, e/d wrist, r/f elbow, u/j shoulder, "
        "i/k base, l/p light on/off, ? help, q quit. No Enter needed.",
    )
    p.set_defaults(func=_keys)
    p = sub.add_parser(
        "pick-place", help="OWI-535: pick the object at A up and put it down at B (mm, world frame)"
    )
    for name in ("ax", "ay", "az", "bx", "by", "bz"):
        p.add_argument(
            name, type=coordinate, metavar=name.upper(), help=f"{name[0].upper()} {name[1]} [mm]"
        )
    p.add_argument(
        "--lift",
        type=number("mm", 0.0, 500.0),
        default=40.0,
        metavar="MM",
        help="travel height above A and B [mm], 0..500 (default 40)",
    )
    p.set_defaults(func=_pick_place)
    p = sub.add_parser(
        "rehome", help="OWI-535: drive each joint against its limit so its angle is known again"
    )
    p.set_defaults(func=_rehome)
    p = sub.add_parser("light", help="OWI-535: switch the gripper light on or off")
    p.add_argument("state", choices=("on", "off"))
    p.set_defaults(func=_light)


def _open(args: argparse.Namespace) -> TimedDriver:
    """The OWI driver named by --arm/--driver/--port."""
    from ..drivers.timed import TimedDriver
    from ..model import load_model
    from ._kept import open_kept

    model = load_model(args.arm)
    check_folder(config_dir(), "the config directory")  # the unit's state file
    if "owi535" not in model.drivers:
        raise ArmkitError(
            f"'{args.command}' is for the OWI-535; add --arm owi535 (got {model.name})"
        )
    driver = open_kept(model, args)
    if not isinstance(driver, TimedDriver):
        driver.close()
        raise ArmkitError(
            f"'{args.command}' needs --driver owi535 or sim, not {args.driver_name!r}"
        )
    return driver


def _keys(args: argparse.Namespace) -> int:
    from ..drivers.timed import run_keys

    with closing(_open(args)) as driver:
        return run_keys(driver)


def _pick_place(args: argparse.Namespace) -> int:
    """000's moveItem (``tasks.move_item`` of a point on the bare table): the item whose
    grip point is A to B, travelling ``--lift`` above them, every step planned first
    with the gripper level; each step said as it starts."""
    from ..arm import Arm
    from ..scene import Scene
    from ..tasks import move_item, run_plan

    with closing(_open(args)) as driver:
        arm = Arm(driver.model, driver)
        a, b = (args.ax, args.ay, args.az), (args.bx, args.by, args.bz)
        plan = move_item(arm, Scene("table"), a, b, lift=args.lift, clearance=args.lift, dry_run=True)  # fmt: skip
        run_plan(arm, plan, lambda k, step: print(f"{k}/{len(plan.steps)} {step.label}"))
        _summary(driver)
    return 0


def _rehome(args: argparse.Namespace) -> int:
    from ..drivers.timed import rehome

    with closing(_open(args)) as driver:
        rehome(driver, print)
        _summary(driver)
    return 0


def _light(args: argparse.Namespace) -> int:
    with closing(_open(args)) as driver:
        driver.set_light(args.state == "on")
        print(f"light {args.state}")
    return 0


def _summary(driver: TimedDriver) -> None:
    from ..drivers.timed import status_line

    print(status_line(driver), file=sys.stdout)
