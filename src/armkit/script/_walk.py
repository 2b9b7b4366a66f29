"""Walk a program's statements: bind parameters, loop repeats, call procedures,
and hand each motion to a backend (``_stepper.Stepper``), which plans it and folds
the plan (the check) or carries it out (the run). One walker and one planner for
both, so what is checked is what runs.
"""

from __future__ import annotations

from collections.abc import Hashable, Iterable
from typing import Literal

from .._errors import ArmkitError
from ._ast import (
    Call,
    Define,
    Grip,
    Header,
    Job,
    Loc,
    Move,
    Num,
    PoseDef,
    PoseName,
    Repeat,
    RunMotor,
    Simple,
    Statement,
    Turn,
)
from ._backend import Backend, Frame, ScriptRunError
from ._diagnostics import Diagnostic, suggest
from ._grammar import BLOCKS, COMMANDS
from ._job_checks import JobArgProblem
from ._jobs import JOBS, as_called, job_check
from ._resolve import UNKNOWN, Arg, Fail, Resolver, job_scene

MAX_CALL_DEPTH = 50
CHECK_BUDGET = 20_000  # statements the checker simulates before it stops unrolling repeats
# The longest ``wait`` [s] and the most iterations of one ``repeat`` (or ``--repeat``) a
# script may ask for: more is a slipped unit or digit (``wait 1e9``), not a job an arm
# should be left alone with; a longer pause is a loop of waits.
MAX_WAIT_S = 3600.0
MAX_REPEAT = 10_000


class Walker:
    """Executes statements on a backend; with ``checking``, problems are collected
    as diagnostics and the walk goes on, else the first raises ``ScriptRunError``."""

    def __init__(self, resolver: Resolver, backend: Backend, source: str, *, checking: bool):
        self.resolver, self.backend, self.source, self.checking = (
            resolver,
            backend,
            source,
            checking,
        )
        self.procs: dict[str, Define] = {}
        self.called: set[str] = set()
        self.frames: list[Frame] = []
        self.diagnostics: list[Diagnostic] = []
        self.steps = 0
        self.budget = CHECK_BUDGET
        self.over_budget = False  # warned that the budget is spent
        self.broken: set[str] = set()  # procedures whose definition did not parse
        self.redefine = False  # a procedure may be defined again (the shell)
        self.first_error: Diagnostic | None = None  # the first met where it would run
        self._unrun = 0  # inside bodies that do not run as written (repeat 0, ...)

    def walk(self, statements: Iterable[Statement]) -> None:
        """Execute ``statements`` in order."""
        for s in statements:
            self._one(s)

    def finish(self) -> None:
        """Checking: walk every procedure never called, with unknown arguments."""
        if self.checking:
            for name, proc in self.procs.items():
                if name not in self.called:
                    self._blind(proc.body, dict.fromkeys(proc.params, UNKNOWN))

    def _one(self, s: Statement) -> None:
        self.steps += 1
        try:
            self._dispatch(s)
        except ScriptRunError:
            raise
        except Fail as f:
            self._failed(s)
            self._report(f.loc, f.message)
        except (ArmkitError, ValueError) as exc:
            self._failed(s)
            self._report(s.loc, str(exc))

    def _failed(self, s: Statement) -> None:
        """Checking goes on after a failed statement without cascading: a pose it meant
        to define and the arm's position become unknown."""
        if isinstance(s, PoseDef):
            self.resolver.poses[s.name] = None
        if self.checking:
            self.backend.lose_track()

    def _report(
        self, loc: Loc, message: str, severity: Literal["error", "warning"] = "error"
    ) -> None:
        if not self.checking:
            raise ScriptRunError(self.source, loc, message, tuple(self.frames))
        notes = tuple(
            f.describe() for f in reversed(self.frames) if f.kind == "call" or f.iteration > 1
        )
        found = Diagnostic(loc, message, severity, notes)
        self.diagnostics.append(found)
        if severity == "error" and self.first_error is None and not self._unrun:
            self.first_error = found

    def _dispatch(self, s: Statement) -> None:
        if isinstance(s, Repeat):
            self._repeat(s)
        elif isinstance(s, Define):
            self._define(s)
        elif isinstance(s, Call):
            self._call(s)
        elif not isinstance(s, Header):
            self.backend.begin(s, tuple(self.frames))
            self._motion(s)

    def _motion(self, s: Statement) -> None:
        r, b = self.resolver, self.backend
        if isinstance(s, Move):
            b.move(r.target(s.target, b.here()), s.straight)
        elif isinstance(s, PoseDef):
            r.poses[s.name] = r.target(s.target, b.here())
        elif isinstance(s, Turn):
            b.turn(r.joint(s.joint, s.joint_loc), r.number(s.angle, "angle"), s.relative)
        elif isinstance(s, Grip):
            b.grip(self._width(s))
        elif isinstance(s, RunMotor):
            self._run_motor(s)
        elif isinstance(s, Job):
            args = r.job_args(s.command, s.args, b.here())
            self._check_job(s, args)
            b.job(s.command, args)
        elif isinstance(s, Simple):
            self._simple(s)

    def _check_job(self, s: Job, args: dict[str, object]) -> None:
        """The job's own checks of its arguments (``JobSpec.check``), as it will get
        them, pointing at the argument (check and run alike); skipped while an argument
        is not known before it runs."""
        check = job_check(s.command)
        scene = job_scene(self.resolver.scene)
        values = [*args.values(), *(v for a in args.values() if isinstance(a, tuple) for v in a)]
        if check is None or scene is None or any(v is None for v in values):
            return
        try:
            check(scene, **as_called(s.command, args))
        except JobArgProblem as exc:
            at = [a.loc for name in exc.names for a in s.args if a.name == name]
            raise Fail(at[0] if at else s.loc, str(exc)) from None

    def _simple(self, s: Simple) -> None:
        b, model = self.backend, self.resolver.model
        if s.command == "home":
            b.home()
        elif s.command == "light":
            self._needs_timed("light", s.loc)
            b.light(s.flag)
        elif s.value is not None and s.command == "wait":
            seconds = self.resolver.number(s.value, "time")
            if seconds is not None and not 0 <= seconds <= MAX_WAIT_S:
                raise Fail(
                    s.loc,
                    f"wait needs a time in 0..{MAX_WAIT_S:g} s (1 hour, the longest pause "
                    f"a script may ask for), got {_written(s.value, seconds, 's')}; repeat a "
                    "shorter wait for more",
                )
            b.wait(seconds)
        elif s.value is not None:
            tool = s.command == "tool-speed"
            v = self.resolver.number(s.value, "speed" if tool else "percent")
            if v is not None and tool and not 0 < v <= 1.0:
                raise Fail(s.loc, f"a tool speed must be in (0, 1000] mm/s, got {v * 1000:g} mm/s")
            if v is not None and not tool and not 0 < v <= 1.0:
                raise Fail(
                    s.loc,
                    f"speed must be in (0, 100] % of {model.name}'s joint speeds, got {v * 100:g} %",
                )
            b.speed(v, tool)

    def _width(self, s: Grip) -> float | None:
        g, name = self.resolver.model.gripper, self.resolver.model.name
        if s.width is None:
            return g.width_max if s.state == "open" else g.width_min
        w = self.resolver.number(s.width, "length")
        if w is not None and not g.width_min - 1e-9 <= w <= g.width_max + 1e-9:
            raise Fail(
                s.width.loc,
                f"grip {w * 1000:g} mm is outside {name}'s {g.width_min * 1000:g}..{g.width_max * 1000:g} mm; "
                "choose a width in that range (or grip open / grip close)",
            )
        return w

    def _run_motor(self, s: RunMotor) -> None:
        r = self.resolver
        joint = r.joint(s.joint, s.joint_loc)
        self._needs_timed("run", s.loc)
        base = r.model.joint_index(joint) == 0
        if base != (s.word in ("left", "right")):
            words = "left or right" if base else "forward or backward"
            raise Fail(s.loc, f"the {joint} turns {words}, not {s.word}")
        seconds = r.number(s.seconds, "time")
        if seconds is not None and not 0 < seconds <= 60:
            raise Fail(s.loc, f"run needs a time in (0, 60] s, got {seconds:g} s")
        self.backend.run_motor(joint, s.direction, seconds)

    def _needs_timed(self, command: str, loc: Loc) -> None:
        model = self.resolver.model
        if model.gripper.kind != "timed":
            hint = "; use 'turn JOINT by ANGLE'" if command == "run" else ""
            raise Fail(
                loc,
                f"'{command}' needs an arm with timed motors (the OWI-535), not {model.name}{hint}",
            )

    def _repeat(self, s: Repeat) -> None:
        n = self.resolver.number(s.count, "count")
        if n is not None and not 0 <= n <= MAX_REPEAT:
            what = "--repeat" if s.loc.line == 0 else "a repeat count"
            raise Fail(
                s.count.loc,
                f"{what} must be 0..{MAX_REPEAT} (more is a slip of a digit, not a job to "
                f"leave an arm with), got {_written(s.count, n, '')}",
            )
        if n is None or n == 0:
            if self.checking:
                self._blind(s.body, None)
            return
        count = int(n)
        before: tuple[Hashable | None, float] = (None, 0.0)
        for i in range(1, count + 1):
            now = (self._snapshot(), self.backend.elapsed())
            if now[0] is not None and now[0] == before[0]:
                self.backend.skip(count - i + 1, now[1] - before[1], s.loc)
                return
            if self.checking and self.steps > self.budget:
                self._report(
                    s.loc,
                    f"checked the first {i - 1} of {count} iterations only (too many "
                    "to simulate); the rest are checked as they run",
                    "warning",
                )
                return
            before = now
            self.frames.append(Frame("repeat", "repeat", s.loc, i, count))
            try:
                self.walk(s.body)
            finally:
                self.frames.pop()

    def _over_budget(self, loc: Loc) -> None:
        """Checking: the budget of simulated statements is spent; warn once, check no more
        calls (each is checked as it runs)."""
        if not self.over_budget:
            self.over_budget = True
            self._report(
                loc,
                f"checked the first {self.budget} statements only (procedures call "
                "too many to simulate); the rest are checked as they run",
                "warning",
            )

    def _snapshot(self) -> Hashable | None:
        state = self.backend.snapshot()
        if state is None:
            return None
        return state, tuple(sorted((k, repr(v)) for k, v in self.resolver.poses.items()))

    def _define(self, s: Define) -> None:
        if s.name in self.procs and not self.redefine:
            first = self.procs[s.name].loc.line
            raise Fail(s.loc, f"procedure {s.name!r} is already defined on line {first}")
        self.procs[s.name] = s

    def _call(self, s: Call) -> None:
        proc = self.procs.get(s.name)
        if proc is None and s.name in self.broken:
            return  # its definition was already reported
        if proc is None:
            raise Fail(s.loc, self._unknown(s.name))
        if len(s.args) != len(proc.params):
            params = ", ".join(proc.params) or "none"
            raise Fail(
                s.loc, f"{s.name} takes {len(proc.params)} arguments ({params}), got {len(s.args)}"
            )
        if self.checking and self.steps > self.budget:
            self._over_budget(s.loc)
            return
        if sum(f.kind == "call" for f in self.frames) >= MAX_CALL_DEPTH:
            raise Fail(
                s.loc,
                f"procedures call each other more than {MAX_CALL_DEPTH} deep; "
                f"{s.name} must not call itself, directly or through another",
            )
        binding = {p: self._arg(a) for p, a in zip(proc.params, s.args, strict=True)}
        self.called.add(s.name)
        self.resolver.bindings.append(binding)
        self.frames.append(Frame("call", s.name, s.loc))
        try:
            self.walk(proc.body)
        finally:
            self.frames.pop()
            self.resolver.bindings.pop()

    def _arg(self, a: Num | PoseName) -> Arg:
        if isinstance(a, PoseName):
            scope = self.resolver.bindings[-1]
            return scope.get(a.name, a.name)
        return a

    def _unknown(self, name: str) -> str:
        if name in self.resolver.poses:
            return f"{name!r} is a pose, not a command; write 'move {name}'"
        words = [*COMMANDS, *JOBS, *BLOCKS, *self.procs]
        return f"unknown command {name!r}{suggest(name, words)}"

    def _blind(self, body: tuple[Statement, ...], binding: dict[str, Arg] | None) -> None:
        """Check names and units of ``body`` without a known arm state (nothing recorded)."""
        poses = dict(self.resolver.poses)
        if binding is not None:
            self.resolver.bindings.append(binding)
        self._unrun += 1
        try:
            with self.backend.blind():
                self.walk(body)
        finally:
            self._unrun -= 1
            if binding is not None:
                self.resolver.bindings.pop()
            self.resolver.poses = poses


def _written(value: object, si: float, unit: str) -> str:
    """A number for a message as the script wrote it and in ``unit`` (``61 min (3660 s)``,
    ``3601 s``), to 6 significant digits."""
    in_unit = f"{si:.6g} {unit}".strip()
    if isinstance(value, Num) and value.unit not in (None, unit):
        return f"{value.value:.6g} {value.unit} ({in_unit})"
    return in_unit
