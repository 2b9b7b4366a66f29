"""Check a whole script before anything moves: parse it, choose the arm and scene
its header names, and fold its plans from a ``Start`` (the plans ``armkit run`` makes,
each from where the one before ends), collecting every problem and the plan with its
time."""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from .._errors import ArmkitError
from .._input_limits import LimitError
from ..arm import Start
from ..connect import driver_names
from ..model import ArmModel, load_model, shipped_models
from ..scene import Scene, load_scene, shipped_scenes
from ._ast import Define, Header, Loc, Num, Program, Repeat, Source, Statement
from ._diagnostics import Diagnostic, ScriptCheckError, sorted_unique, suggest
from ._fold import Fold
from ._now import start_of
from ._parse import parse
from ._planning import Pace
from ._resolve import Resolver, SceneInfo, Target, job_scene
from ._stepper import Stepper
from ._timetable import Timetable
from ._walk import Walker

if TYPE_CHECKING:
    from ..arm import Arm

F64 = NDArray[np.float64]
DEFAULT_ARM = "openmanipulator_x"
RUN_LOOP = Loc(0, 0)  # where ``--repeat N`` puts its loop


@dataclass(frozen=True)
class Setup:
    """What the script's header chose (None: not written): its ``arm``, ``driver``
    (``driver_line``) and ``scene`` lines."""

    arm: Header | None = None
    driver_line: Header | None = None
    scene: Header | None = None


@dataclass
class Env:
    """Poses, procedures and speeds known before a script starts (the shell's session)."""

    poses: dict[str, Target | None] = field(default_factory=dict)
    procs: dict[str, Define] = field(default_factory=dict)
    pace: Pace = field(default_factory=Pace)


@dataclass
class CheckResult:
    """A checked script.

    Attributes:
        program: the statements.  model: the arm it was checked for.
        timetable: every motion with its time.  diagnostics: every problem, in line order.
        setup: the header.  scene: the scene, if one was chosen.
        first_error: the error the script meets first as it runs (where ``armkit run``
            would stop), or None.
    """

    program: Program
    model: ArmModel
    timetable: Timetable
    setup: Setup
    scene: SceneInfo | None
    diagnostics: list[Diagnostic] = field(default_factory=list)
    first_error: Diagnostic | None = None

    @property
    def ok(self) -> bool:
        """No errors (warnings allowed)."""
        return not any(d.severity == "error" for d in self.diagnostics)

    def raise_if_failed(self) -> None:
        """``ScriptCheckError`` listing every problem, if there is an error."""
        if not self.ok:
            raise ScriptCheckError(self.program.source, self.diagnostics)


def setup_of(program: Program) -> Setup:
    """The ``arm``, ``driver`` and ``scene`` lines of ``program``."""
    found = {s.kind: s for s in program.statements if isinstance(s, Header)}
    return Setup(found.get("arm"), found.get("driver"), found.get("scene"))


def check_source(
    source: Source,
    *,
    model: ArmModel | None = None,
    scene: SceneInfo | None = None,
    arm: Arm | None = None,
    start: Start | None = None,
    carried: Scene | None = None,
    repeat: int = 1,
    base_dir: Path | None = None,
    env: Env | None = None,
) -> CheckResult:
    """Parse and check ``source`` whole.

    Args:
        model: the arm (None: the script's ``arm`` line, else openmanipulator_x).
        scene: the scene (None: the script's ``scene`` line, if any).
        arm: the arm it will run on, as it is now (its joints, grip, held cube, driver's
            forecasts, a simulated arm's objects where they are); None: the model at
            home, nothing held, the scene's file, the model's own driver.
        start: where it starts, if not from ``arm`` (None: the model at home); its
            scene, if it has none, the script's.
        carried: the scene's objects as the statements before left them (the shell).
        repeat: run the whole script this many times (``--repeat``).
        base_dir: where relative file names start (default: the script's folder).
        env: poses and procedures already defined (copied, not changed).
    """
    program, diagnostics = parse(source)
    setup = setup_of(program)
    here = base_dir or Path(source.name).parent
    if model is None:
        model = _model_from(setup.arm, here, diagnostics)
    if model is None:
        found = sorted_unique(diagnostics)
        first = next((d for d in diagnostics if d.severity == "error"), None)
        return CheckResult(
            program, load_model(DEFAULT_ARM), Timetable(()), setup, None, found, first
        )
    _check_arm(setup.arm, model, diagnostics)
    _check_driver(setup.driver_line, diagnostics)
    if scene is None and setup.scene is not None:
        scene = load_scene_info(setup.scene.value, here, setup.scene.value_loc, diagnostics)
    objects = job_scene(scene)
    start = _start(model, arm or start, scene, carried or objects)
    fold = Fold(start, objects or Scene("unknown"), model.joint_names)
    stepper = Stepper(fold)
    walker = Walker(Resolver(model, scene, here), stepper, source.name, checking=True)
    stepper.pace = Pace() if env is None else env.pace
    _seed(walker, program, env)
    walker.walk(looped(program.statements, repeat))
    walker.finish()
    # a parse, arm, driver or scene error stops a run before its first statement
    first = next((d for d in diagnostics if d.severity == "error"), walker.first_error)
    diagnostics += walker.diagnostics
    return CheckResult(program, model, fold.table, setup, scene, sorted_unique(diagnostics), first)


def _start(
    model: ArmModel, arm: Arm | Start | None, info: SceneInfo | None, objects: Scene | None
) -> Start | None:
    """Where the script starts: ``arm`` as it is (or that Start), else ``model`` at home,
    with the scene's ``objects`` (None: the script names no scene, or it cannot be
    loaded: nothing is planned)."""
    scene = None if info is None else objects
    if info is not None and objects is None:
        return None
    if isinstance(arm, Start):
        return arm if arm.scene is not None or scene is None else arm.then(scene=scene)
    if arm is not None:
        return start_of(arm, scene)
    return Start(model, model.home, scene=scene)


def _seed(walker: Walker, program: Program, env: Env | None) -> None:
    """What the walk knows before the first statement: the session's poses and
    procedures, and the names whose definitions did not parse (not reported again)."""
    if env is not None:
        walker.resolver.poses.update(env.poses)
        walker.procs.update(env.procs)
        walker.called.update(env.procs)
        walker.redefine = True
    walker.resolver.poses.update(dict.fromkeys(program.broken))
    walker.broken = set(program.broken)


def looped(statements: tuple[Statement, ...], repeat: int) -> tuple[Statement, ...]:
    """The statements run ``repeat`` times (``--repeat``): procedures are defined once,
    before the loop."""
    if repeat == 1:
        return statements
    defines = tuple(s for s in statements if isinstance(s, Define))
    rest = tuple(s for s in statements if not isinstance(s, Define))
    return (*defines, Repeat(Num(repeat, None, RUN_LOOP), rest, RUN_LOOP))


def check_file(path: str | Path, **options: Any) -> CheckResult:
    """``check_source`` on a file (same options)."""
    try:
        source = Source.read(path)
    except LimitError as exc:
        at = Loc(max(exc.line, 1), max(exc.column, 1))
        raise ScriptCheckError(Source(str(path), ""), [Diagnostic(at, exc.problem)]) from None
    return check_source(source, **options)


def _model_from(
    header: Header | None, here: Path, diagnostics: list[Diagnostic]
) -> ArmModel | None:
    if header is None:
        return load_model(DEFAULT_ARM)
    name = header.value
    local = here / name
    try:
        return load_model(local if name.endswith(".toml") and local.exists() else name)
    except (ArmkitError, ValueError, OSError) as exc:
        hint = suggest(name, shipped_models())
        message = (
            f"unknown arm {name!r}{hint} (shipped: {', '.join(shipped_models())}, or a .toml file)"
        )
        if name.endswith(".toml"):
            message = str(exc)
        diagnostics.append(Diagnostic(header.value_loc, message))
        return None


def _check_arm(header: Header | None, model: ArmModel, diagnostics: list[Diagnostic]) -> None:
    if header is not None and model.name not in (header.value, Path(header.value).stem):
        diagnostics.append(
            Diagnostic(
                header.value_loc,
                f"this script is for {header.value}, but the arm is {model.name}; "
                f"run it with --arm {header.value} or change its 'arm' line",
            )
        )


def _check_driver(header: Header | None, diagnostics: list[Diagnostic]) -> None:
    if header is not None and header.value not in driver_names():
        names = driver_names()
        diagnostics.append(
            Diagnostic(
                header.value_loc,
                f"unknown driver {header.value!r}{suggest(header.value, names)} (drivers: {', '.join(names)})",
            )
        )


def load_scene_info(
    label: str, here: Path, loc: Loc, diagnostics: list[Diagnostic]
) -> SceneInfo | None:
    """The scene a ``scene`` line names (a file next to the script, or a shipped
    scene's name)."""
    try:
        scene = load_scene(_scene_source(label, here))
    except (ArmkitError, ValueError, OSError) as exc:
        diagnostics.append(Diagnostic(loc, f"scene {label!r}: {exc}"))
        return None
    return SceneInfo(label, frozenset(scene_names(scene)), scene)


def _scene_source(label: str, here: Path) -> Path | str:
    """A file next to the script, a path, or a shipped scene's name (``board_001``)."""
    for candidate in (here / label, Path(label)):
        if candidate.is_file():
            return candidate
    stem = Path(label).stem
    return stem if stem in shipped_scenes() else here / label


def scene_names(scene: object) -> Iterator[str]:
    """Every named thing of a scene: boards, cubes, containers, pens, stands, sheets, instruments, places."""
    for group in (
        "boards",
        "cubes",
        "containers",
        "pens",
        "pen_stands",
        "sheets",
        "instruments",
        "places",
    ):
        items = getattr(scene, group, ())
        for item in items.values() if isinstance(items, dict) else items:
            name = getattr(item, "name", None)
            if isinstance(name, str):
                yield name
