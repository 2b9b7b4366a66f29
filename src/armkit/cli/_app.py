"""Parser, global options and the one place where errors become one line."""

from __future__ import annotations

import argparse
import importlib
import sys
from collections.abc import Sequence

from .._errors import ArmkitError
from ._parser import Parser

# Modules that add sub-commands: each defines ``add_commands(sub)`` and its
# handlers take the parsed ``args`` and return an exit code.
COMMAND_MODULES = (
    "armkit.cli._info",
    "armkit.cli._kinematics",
    "armkit.cli._demo",
    "armkit.cli._motion",
    "armkit.cli._servo",
    "armkit.cli._owi",
    "armkit.cli._calibrate",
    "armkit.cli._compare",
    "armkit.cli._dynamixel",
    "armkit.cli._urdf",
)

EPILOG = """\
units: positions in millimetres, angles in degrees, in armkit's world frame
(x forward, y left, z up, origin at the centre of the base on the table).
Pitch is the gripper's angle above the horizontal: 0 = level, -90 = pointing down.

examples:
  armkit arms
  armkit --arm owi535 show
  armkit --arm openmanipulator_x ik 200 0 50 --pitch -90 --all
  armkit --arm lynx6 fk 90 90 90 90 90
"""


def build_parser() -> argparse.ArgumentParser:
    """The full parser with every command module's sub-commands."""
    parser = Parser(
        prog="armkit",
        description="Drive cheap robot arms by where the gripper should go.",
        epilog=EPILOG,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    parser.add_argument(
        "--arm",
        default="openmanipulator_x",
        metavar="NAME|FILE",
        help="shipped arm name (see 'armkit arms') or a model .toml file "
        "(default: openmanipulator_x)",
    )
    parser.add_argument(
        "--driver",
        default="sim",
        metavar="NAME",
        help="driver: sim (default), owi535, ssc32, maestro, dynamixel",
    )
    parser.add_argument(
        "--port",
        default=None,
        metavar="PORT",
        help="serial port or device for the driver ('emu' = emulator)",
    )
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")
    for name in COMMAND_MODULES:
        importlib.import_module(name).add_commands(sub)
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    """Run the CLI; user mistakes print one line on stderr and exit non-zero."""
    parser = build_parser()
    args = parser.parse_args(argv)
    if args.command is None:
        parser.print_help()
        return 0
    try:
        return int(args.func(args) or 0)
    except (ArmkitError, ValueError) as exc:
        print(f"armkit: error: {exc}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print("armkit: interrupted", file=sys.stderr)
        return 130
