"""Parser, global options and the one place where errors become one line."""

from __future__ import annotations

import argparse
import os
import sys
import warnings
from collections.abc import Sequence
from typing import Any, TextIO

from .. import __version__
from .._errors import ArmkitError, ArmkitWarning, InputError
from ..connect import driver_kinds, listed
from ..jobs import CLI_JOBS, JOBS
from . import (
    _calibrate,
    _compare,
    _demo,
    _dynamixel,
    _emulate,
    _info,
    _jobs,
    _kinematics,
    _motion,
    _owi,
    _play,
    _scene,
    _script,
    _servo,
    _tasks,
    _urdf,
    _view,
)
from ._parser import Parser

# Modules that add sub-commands, in the order ``armkit --help`` lists them: each defines
# ``add_commands(sub)`` and its handlers take the parsed ``args`` and return an exit code.
COMMAND_MODULES = (
    _info,
    _kinematics,
    _demo,
    _motion,
    _servo,
    _owi,
    _calibrate,
    _compare,
    _dynamixel,
    _emulate,
    _view,
    _script,
    _scene,
    _tasks,
    _urdf,
    _play,
    _jobs,
)

EPILOG = """\
units: positions in millimetres, angles in degrees, in armkit's world frame
(x forward, y left, z up, origin at the centre of the base on the table).
Pitch is the gripper's angle above the horizontal: 0 = level, -90 = pointing down.

examples:
  armkit arms
  armkit --arm owi535 show
  armkit --arm openmanipulator_x ik 200 0 50 --pitch -90 --all
  armkit --arm lynx6 ik 200 0 50 --pitch -45 --all
  armkit --arm lynx6 fk 90 90 90 90 90
"""


def parser_of_process() -> argparse.ArgumentParser:
    """The parser ``main`` uses, built once per process (building it imports every command
    module and adds some 50 sub-parsers: about 40 ms, more than most commands take) and
    again only if the registry of driver kinds it lists was replaced since, or the jobs
    (``armkit.jobs.JOBS``) changed. Parsing leaves a parser as it was, so one
    parser serves every call of ``main``."""
    kinds, jobs = driver_kinds(), (*JOBS.items(), *CLI_JOBS.items())
    if _BUILT.get("kinds") is not kinds or _BUILT.get("jobs") != jobs:
        _BUILT.update(kinds=kinds, jobs=jobs, parser=build_parser())
    parser: argparse.ArgumentParser = _BUILT["parser"]
    return parser


_BUILT: dict[str, Any] = {}  # the parser parser_of_process built, and the kinds it lists


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
        action=Given,
        metavar="NAME|FILE",
        help="shipped arm name (see 'armkit arms') or a model .toml file "
        "(default: openmanipulator_x)",
    )
    parser.add_argument(
        "--driver",
        dest="driver_name",
        default="sim",
        metavar="NAME",
        help=f"driver: sim (default), {', '.join(kind.name for kind in driver_kinds())}",
    )
    serial = [kind.name for kind in driver_kinds() if kind.port == "serial"]
    parser.add_argument(
        "--port",
        default=None,
        metavar="PORT",
        help=f"the serial port or device of {listed(serial, 'and')} (/dev/ttyUSB0; they "
        "need one), or 'emu' for an emulated device; with --driver sim, a state file "
        "(arm.json) that keeps that simulated arm between commands (default: none, the "
        "simulated arm kept in $ARMKIT_CONFIG_DIR/sim_<arm>.json)",
    )
    parser.add_argument(
        "--scene",
        default=None,
        metavar="FILE|NAME",
        help="what is on the table: a scene .toml file (mm, deg) or a shipped scene "
        "(see 'armkit scene list'); tasks and moves are checked against it (default: none, "
        "an empty table)",
    )
    parser.add_argument(
        "--physics",
        choices=("rules", "mujoco"),
        default=None,
        help="what moves the scene's objects in the simulator: rules (armkit's own: a cube "
        "between the jaws is grasped, a released one settles) or mujoco (MuJoCo's contacts, "
        "friction and gravity; pip install 'armkit[physics]'); default: the scene file's "
        "'physics', else rules",
    )
    parser.add_argument(
        "--explain",
        action="store_true",
        help="on a refusal, say more than its one line: each way tried and why it failed",
    )
    parser.add_argument("--version", action="version", version=f"armkit {__version__}")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")
    for module in COMMAND_MODULES:
        module.add_commands(sub)
    return parser


class Given(argparse.Action):
    """Stores the option's value and notes that it was given, not defaulted: its dest
    joins ``args.given`` (a command with its own default, as 'emulate', can tell)."""

    def __call__(self, parser: Any, namespace: Any, values: Any, option: Any = None) -> None:
        setattr(namespace, self.dest, values)
        namespace.given = {*getattr(namespace, "given", ()), self.dest}


def main(argv: Sequence[str] | None = None) -> int:
    """Run the CLI; user mistakes print one line on stderr and exit non-zero."""
    parser = parser_of_process()
    words = list(sys.argv[1:] if argv is None else argv)
    try:
        misplaced = _misplaced_global(parser, words)
        if misplaced:
            parser.error(misplaced)
        args = parser.parse_args(words)
    except SystemExit as exc:  # --help, or a mistake argparse found (one line printed)
        return exc.code if isinstance(exc.code, int) else 2
    with warnings.catch_warnings():
        warnings.showwarning = _show_warning
        return _run(parser, args)


def _run(parser: argparse.ArgumentParser, args: argparse.Namespace) -> int:
    """Do the parsed command: every refusal one line on stderr and a non-zero exit."""
    try:
        _check_globals(args)
        if args.command is None:
            parser.print_help()
            return 0
        code = int(args.func(args) or 0)
        sys.stdout.flush()  # a closed pipe shows here, not in the interpreter's exit
        return code
    except ArmkitError as exc:
        _refused(exc, bool(getattr(args, "explain", False)))
        return 2
    except BrokenPipeError:  # `armkit ... | head`: the reader left; stop quietly, as `cat` does
        _silence_stdout()
        return 141
    except OSError as exc:  # the disk, not armkit: still one line
        print(f"armkit: error: {_one_line(exc)}", file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        print("armkit: interrupted", file=sys.stderr)
        return 130


def _refused(exc: ArmkitError, explain: bool) -> None:
    """The refusal's one line; its details below it with ``--explain``, else a hint."""
    line = _one_line(exc)
    if exc.details and not explain:
        line += " (--explain: more)"
    print(f"armkit: error: {line}", file=sys.stderr)
    if exc.details and explain:
        for detail in exc.details.splitlines():
            print(f"  {detail}", file=sys.stderr)


def _show_warning(
    message: Warning | str,
    category: type[Warning],
    filename: str,
    lineno: int,
    file: TextIO | None = None,
    line: str | None = None,
) -> None:
    """armkit's own warnings as one ``armkit: warning: ...`` line; others as Python shows them."""
    if issubclass(category, ArmkitWarning):
        print(f"armkit: warning: {_one_line(Exception(message))}", file=file or sys.stderr)
    else:
        sys.stderr.write(warnings.formatwarning(message, category, filename, lineno, line))


def _silence_stdout() -> None:
    """Point stdout at /dev/null so the interpreter's final flush cannot fail again."""
    devnull = os.open(os.devnull, os.O_WRONLY)
    os.dup2(devnull, sys.stdout.fileno())
    os.close(devnull)


def _one_line(exc: BaseException) -> str:
    return " ".join(str(exc).split()) or type(exc).__name__


def _check_globals(args: argparse.Namespace) -> None:
    """--arm names a model that loads, --driver a known driver, --port is not empty."""
    from ..connect import driver_names
    from ..model import load_model

    load_model(args.arm)
    if args.driver_name not in driver_names():
        raise InputError(
            f"unknown driver {args.driver_name!r} (--driver); drivers are {', '.join(driver_names())}"
        )
    if args.port is not None and not args.port.strip():
        raise InputError("--port is empty; give a device (/dev/ttyUSB0) or 'emu'")
    if getattr(args, "physics", None) == "mujoco":
        from ..physics import mujoco_module

        mujoco_module()  # one line saying how to install it, before anything moves


def _global_options(parser: argparse.ArgumentParser) -> set[str]:
    return {
        opt
        for action in parser._actions
        if action.option_strings and not isinstance(action, argparse._HelpAction)
        for opt in action.option_strings
    }


def _knows(parser: argparse.ArgumentParser, option: str) -> bool:
    """Whether ``parser`` or one of its sub-command parsers takes ``option``."""
    if option in parser._option_string_actions:
        return True
    subs = [a for a in parser._actions if isinstance(a, argparse._SubParsersAction)]
    return any(_knows(p, option) for sub in subs for p in sub.choices.values())


def _misplaced_global(parser: argparse.ArgumentParser, words: list[str]) -> str | None:
    """A one-line hint when a global option (--arm, --driver, ...) follows the command."""
    options = _global_options(parser)
    subs = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    k = 0
    while k < len(words) and words[k] not in subs.choices:
        if words[k] in ("--", "-h", "--help"):
            return None
        k += 1 + (words[k] in options)
    if k >= len(words):
        return None
    command, rest = words[k], words[k + 1 :]
    for i, word in enumerate(rest):
        option = word.split("=", 1)[0]
        if option in options and not _knows(subs.choices[command], option):
            takes = "=" not in word and i + 1 < len(rest)
            moved = [word, rest[i + 1]] if takes else [word]
            kept = rest[:i] + rest[i + 1 + takes :]
            fixed = " ".join(["armkit", *words[:k], *moved, command, *kept])
            return f"{option} is a global option and goes before the command: {fixed}"
    return None
