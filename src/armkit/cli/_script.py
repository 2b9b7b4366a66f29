"""The command language: ``armkit run FILE``, ``armkit check FILE``, ``armkit shell``.

A script's ``arm``/``driver``/``scene`` lines choose what the global options
would; a global option left at its default gives way to the script, one set to
something else must agree with it.
"""

from __future__ import annotations

import argparse
import contextlib
import sys
from pathlib import Path
from typing import TYPE_CHECKING, Any

from .._errors import ArmkitError, InputError
from .._files import config_dir
from .._terminal import count
from ..connect import kinds_of
from ._open_arm import open_arm
from ._watch import add_watch_options

if TYPE_CHECKING:
    from ..arm import Arm
    from ..script import Frame, Header, SceneInfo, Setup, Source, Statement

DEFAULTS = {"arm": "openmanipulator_x", "driver_name": "sim"}  # the options a script may choose
UNITS_NOTE = (
    "Scripts are in mm, degrees and seconds unless a unit is written (cm, m, in, rad, ms, "
    "min, %, mm/s). The grammar: 'armkit shell' then 'help', or the documentation's Scripts page (docs/scripts.md)."
)
SHELL_EPILOG = (
    """\
the shell's own words (besides the language):
  where | poses | help [WORD] | run FILE | quit
  jog [STEP_DEG]   jog with keys, one step a key (i/k j/u f/r d/e g/t h/y joints 1-6,
                   w/s close/open, v save, q leaves); the OWI runs 250 ms a key
  limp             torque off: move the arm by hand (Dynamixel arms; support it first);
                   refused on hobby servos (SSC-32, Maestro) and the OWI, which report
                   no position
  hold             torque on where the arm is (the hand-moved pose is recorded)
  save NAME        keep the pose now (while limp: the servos' true angles)
  write FILE       the session as a script that armkit run replays

a block (repeat ... end, define ... end) runs when its 'end' is typed; 'quit' inside
one drops it. With lines piped in (not a terminal) the exit status is 1 if any line
failed, else 0; at a terminal it is 0.

example (typed at the shell's prompt, the arm moved by hand after limp):
  $ armkit shell
  ... p 0> limp
  ... p 0 limp> save grab
  ... p -30 limp> hold
  ... p -30> write taught.arm
  $ armkit run taught.arm

"""
    + UNITS_NOTE
)


def add_commands(sub: argparse._SubParsersAction[Any]) -> None:
    """Add run, check and shell."""
    p = sub.add_parser(
        "run", help="check a .arm script whole, then run it", epilog=UNITS_NOTE,
        description="Check the whole script (every problem listed, nothing moves if there is "
        "one), then run it on the arm, printing each line as it runs.",
    )  # fmt: skip
    p.add_argument("file", metavar="FILE", help="the script (.arm)")
    p.add_argument(
        "--dry-run", action="store_true", help="print the plan and its time [s]; move nothing"
    )
    p.add_argument(
        "--repeat",
        type=int,
        default=1,
        metavar="N",
        help="run the whole script N times (1..10000, default 1)",
    )
    p.add_argument("-q", "--quiet", action="store_true", help="do not print each line as it runs")
    add_watch_options(p)
    p.set_defaults(func=_run)
    p = sub.add_parser(
        "check", help="check a .arm script without moving: every error with line and column",
        epilog=UNITS_NOTE,
        description="Check the whole script from the arm's home pose, with the scene's cubes "
        "where its file puts them: every target, move and straight line (reach, joint limits, "
        "the table, the base column, the scene's objects), every job's arguments, every task "
        "planned whole, and the time it takes. 'armkit run --dry-run FILE' checks it from where "
        "the arm is now, with the cubes where a simulated arm keeps them.",
    )  # fmt: skip
    p.add_argument("file", metavar="FILE", help="the script (.arm)")
    p.add_argument(
        "--plan", action="store_true", help="also print the plan (from home) and its time [s]"
    )
    p.set_defaults(func=_check)
    p = sub.add_parser(
        "shell", help="the script language interactively: history, Tab completion, jog, "
        "limp/hold, teach", epilog=SHELL_EPILOG, formatter_class=argparse.RawDescriptionHelpFormatter,
    )  # fmt: skip
    p.add_argument(
        "--no-history", action="store_true", help="do not read or write the history file"
    )
    p.set_defaults(func=_shell)


def _check(args: argparse.Namespace) -> int:
    from ..model import load_model
    from ..script import check_source

    source, setup = _read(args.file)
    arm = _choose(args, "arm", setup.arm, source)
    scene = _scene(args)
    model = load_model(arm) if arm != (setup.arm.value if setup.arm else None) else None
    _choose(args, "driver_name", setup.driver_line, source)  # the script's, or refused
    result = check_source(source, model=model, scene=scene)
    _report(result)
    result.raise_if_failed()
    if args.plan:
        print(result.timetable.format(source))
    table = result.timetable
    later = f" (+{table.unknown} timed when run)" if table.unknown else ""
    if any("timed" in kind.traits for kind in kinds_of(result.model)):  # each unit's own rates
        later += "; timed as a new unit runs: 'armkit run --dry-run' times this unit"
    print(
        f"{source.name}: ok for {result.model.name}: {count(len(table.rows), 'step')}, {table.total:.2f} s from home{later}"
    )
    return 0


def _run(args: argparse.Namespace) -> int:
    from ..script import MAX_REPEAT, check_source, run_checked

    if not 1 <= args.repeat <= MAX_REPEAT:
        raise InputError(f"--repeat must be 1..{MAX_REPEAT}, got {args.repeat}")
    source, setup = _read(args.file)
    with _open(args, setup, source) as arm:
        result = check_source(
            source, model=arm.model, scene=_scene(args), arm=arm,
            repeat=args.repeat,
        )  # fmt: skip
        _report(result)
        result.raise_if_failed()
        if args.dry_run:
            print(result.timetable.format(source))
            print("dry run: nothing moved")
            return 0
        t0 = arm.clock.now()
        hook = None if args.quiet else _progress(source)
        run_checked(arm, result, repeat=args.repeat, on_step=hook)
        print(f"done: {source.name} in {arm.clock.now() - t0:.2f} s")
    return 0


def _shell(args: argparse.Namespace) -> int:
    from ..script import Session, Shell

    with _open(args, None, None) as arm:
        session = Session(arm, scene=_scene(args))
        history = None if args.no_history else config_dir() / "shell_history"
        return Shell(session, history=history).loop()


def _read(name: str) -> tuple[Source, Setup]:
    from ..script import Source, parse, setup_of

    source = Source.read(name)
    program, _ = parse(source)
    return source, setup_of(program)


def _choose(args: argparse.Namespace, what: str, header: Header | None, source: Source) -> str:
    """The script's choice where the option (``what``: ``arm`` or ``driver_name``, the
    option ``--driver``) was left at its default, else the option."""
    option: str = getattr(args, what)
    word = what.removesuffix("_name")
    if header is None:
        return option
    value = header.value
    if what == "arm" and value.endswith(".toml"):
        local = Path(source.name).parent / value
        value = str(local) if local.exists() else value
    if option in (DEFAULTS[what], value, Path(value).stem):
        return value
    raise InputError(
        f"{source.name}:{header.loc.line}: the script chooses {word} {header.value} but "
        f"--{word} says {option}; drop the option or change the script"
    )


def _open(
    args: argparse.Namespace, setup: Setup | None, source: Source | None
) -> contextlib.AbstractContextManager[Arm]:
    ns = argparse.Namespace(**vars(args))
    if setup is not None and source is not None:
        ns.arm = _choose(args, "arm", setup.arm, source)
        ns.driver_name = _choose(args, "driver_name", setup.driver_line, source)
        line = setup.driver_line
        if line is not None and line.port is not None and args.port is None:
            ns.port = line.port
        if setup.scene is not None and getattr(args, "scene", None) is None:
            ns.scene = _scene_file(setup.scene, source)  # the arm's moves, kept objects
    return open_arm(ns)


def _scene_file(header: Header, source: Source) -> str | None:
    """The file of the scene a script's ``scene`` line names (None if it cannot be
    loaded: the check says why)."""
    from ..scene import Scene
    from ..script import load_scene_info

    info = load_scene_info(header.value, Path(source.name).parent, header.value_loc, [])
    scene = None if info is None else info.scene
    return str(scene.source) if isinstance(scene, Scene) and scene.source else None


def _scene(args: argparse.Namespace) -> SceneInfo | None:
    label = getattr(args, "scene", None)
    if not label:
        return None
    from ..script import Loc, load_scene_info

    problems: list[Any] = []
    info = load_scene_info(str(label), Path.cwd(), Loc(1, 1), problems)
    for d in problems:
        print(f"armkit: {d.severity}: --scene {label}: {d.message}", file=sys.stderr)
    if info is None:
        raise ArmkitError(f"cannot load the scene {label}")
    return info


def _report(result: Any) -> None:
    for d in result.diagnostics:
        print(d.format(result.program.source), file=sys.stderr)


def _progress(source: Source) -> Any:
    def show(stmt: Statement, frames: tuple[Frame, ...]) -> None:
        text = source.line(stmt.loc.line).split("#")[0].strip()
        where = " ".join(
            f"{f.iteration}/{f.count}" if f.kind == "repeat" else f.name for f in frames
        )
        print(f"{stmt.loc.line:>5}  {text}" + (f"  [{where}]" if where else ""), flush=True)

    return show
