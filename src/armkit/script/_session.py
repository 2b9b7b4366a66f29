"""The shell's session: the language one line (or block) at a time on an open arm,
each chunk checked before it moves, plus the shell's own words (``where``,
``poses``, ``save``, ``write``, ``jog``, ``run FILE``, ``help``, ``quit``).

No process is started per command: the arm stays open, and a chunk costs a
parse, a check on the model and the motion itself.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Iterable
from dataclasses import dataclass, replace
from pathlib import Path

from .._errors import ArmkitError
from .._files import write_atomic
from .._input_limits import MAX_LINE_CHARS, LimitError
from .._terminal import count
from ..arm import Arm
from ..model import ArmModel, load_model, shipped_models
from ._ast import Header, Source
from ._backend import ScriptRunError
from ._check import Env, check_source
from ._diagnostics import ScriptCheckError, compact_numbers
from ._grammar import DIRECTIONS, RESERVED, usage_of
from ._lexer import LexError, Token, tokenize
from ._resolve import JointPose, Resolver, SceneInfo
from ._run import Carry, run_source
from ._stepper import Stepper
from ._teach import Jog, Teaching, joints_line, pose_now, torque
from ._walk import Walker

SHELL_WORDS = ("where", "poses", "save", "write", "jog", "limp", "hold", "help", "quit", "exit")
ARGUMENTS = {"help": "[WORD]", "jog": "[STEP_DEG]", "save": "NAME", "write": "FILE"}
"""The shell words that take one argument ([optional]); the others take none."""
HELP = """\
the language: move, line, joints, turn, grip, home, wait, speed, light, run, pose,
  repeat N ... end, define NAME(P, ...) ... end, and the jobs (help WORD for one)
the shell: where | poses | save NAME | write FILE | jog [STEP_DEG] | run FILE |
  limp (torque off: move the arm by hand, save reads its true angles; Dynamixel) |
  hold (torque on where it is) | help [WORD] | quit  (Tab completes; arrows: history)"""
LIMP = "error: the arm is limp (torque off); type hold before moving it"
ANSWERED_IN_A_BLOCK = ("where", "poses", "help")
"""Shell words that only show something: inside an open block they are answered at once
and the block stays open (the others are refused there, and ``quit`` drops the block)."""


@dataclass
class Reply:
    """What the shell prints after a line, and what to do next."""

    text: str = ""
    more: bool = False  # a block is open: read more lines
    quit: bool = False
    jog: float | None = None  # enter jog mode with this step [deg]
    failed: bool = False  # the line failed: ``text`` is its error


def _error(text: str, *, more: bool = False) -> Reply:
    """A line that failed, with its error (``more``: a block is still open)."""
    return Reply(text, more=more, failed=True)


class Session:
    """The language, interactively, on ``arm`` (see the module doc)."""

    def __init__(self, arm: Arm, *, scene: SceneInfo | None = None, base_dir: Path | None = None):
        self.arm, self.scene = arm, scene
        self.base_dir = base_dir or Path.cwd()
        self.side = Carry(arm, scene)
        self.stepper = Stepper(self.side)
        self.resolver = Resolver(arm.model, scene, self.base_dir)
        self.walker = Walker(self.resolver, self.stepper, "<shell>", checking=False)
        self.walker.redefine = True
        self.teaching = Teaching(arm.model.name, pose_now(arm))
        self.next_line = 1  # the line the next statement starts on
        self._typed = 0  # lines typed so far
        self.limp = False  # torque off (``limp``) until ``hold``
        self._pending: list[str] = []
        self._depth = 0

    @property
    def names(self) -> list[str]:
        """Pose and procedure names defined so far (for completion)."""
        return [*self.resolver.poses, *self.walker.procs]

    def handle(self, line: str) -> Reply:
        """One line typed: a shell word, a statement, or part of a block. Every line
        typed counts in the positions errors name: an error says ``<shell>:LINE:COL:``
        (the line typed, or the first line of the chunk that failed as it ran)."""
        reply = self._handle(line)
        if reply.failed and reply.text.startswith("error: "):
            return replace(reply, text=f"<shell>:{self._typed}:1: {reply.text}")
        return reply

    def _handle(self, line: str) -> Reply:
        if not self._pending:
            self.next_line = self._typed + 1
        self._typed += 1
        if problem := _unreadable_line(line):
            col, what = problem
            if self._pending:
                self._pending.append("")  # the block's lines keep the numbers they were typed on
            return _error(f"<shell>:{self._typed}:{col}: error: {what}", more=bool(self._pending))
        words = line.split()
        if self._pending and ((words[:1] and words[0] in SHELL_WORDS) or _run_file(words)):
            return self._in_block(words)
        if not self._pending and words and words[0] in SHELL_WORDS:
            return self._shell_word(words)
        if not self._pending and _run_file(words):
            return _error(LIMP) if self.limp else self._run_file(words[1])
        if not self._pending and words[:1] == ["run"] and len(words) > 2 and self._not_timed(words):
            return _error(
                f"error: run takes one FILE (run FILE), got {' '.join(words[1:])!r}; a timed "
                "motor is run JOINT forward|backward|left|right TIME"
            )
        self._pending.append(line)
        self._depth += _depth_change(line)
        if self._depth > 0:
            return Reply(more=True)
        text = "\n".join(self._pending)
        self._pending, self._depth = [], 0
        if self.limp and text.strip():
            return _error(LIMP)
        return self.execute(text) if text.strip() else Reply()

    def _in_block(self, words: list[str]) -> Reply:
        """A shell word typed while a block is open: it is never part of the block.
        ``quit`` quits, dropping the block; ``where``, ``poses`` and ``help`` are answered
        and the block stays open; the others are refused and the block stays open."""
        word = words[0]
        if word != "run" and (wrong := _wrong_count(word, words[1:])):
            self._pending.append("")  # the block's lines keep the numbers they were typed on
            return _error(wrong, more=True)
        if word in ("quit", "exit"):
            dropped = f"{word}: {self._open_block()} was dropped: nothing of it ran"
            self.cancel()
            reply = self._shell_word(words)
            return Reply("\n".join(t for t in (dropped, reply.text) if t), quit=True)
        self._pending.append("")
        if word in ANSWERED_IN_A_BLOCK:
            return Reply(self._shell_word(words).text, more=True)
        shown = "run FILE" if word == "run" else word
        return _error(
            f"error: {shown} is a shell word, not a statement a block can hold, and "
            f"{self._open_block()} is open: nothing done; finish the block with end, or quit "
            "to drop it",
            more=True,
        )

    def _open_block(self) -> str:
        """``the repeat block opened at line 2`` (a block is open)."""
        return f"the {self._pending[0].split()[0]} block opened at line {self.next_line}"

    def cancel(self) -> None:
        """Drop a half-typed block (Ctrl-C at the prompt)."""
        self._pending, self._depth = [], 0

    def end_of_input(self) -> Reply:
        """The input ended: a half-typed block is dropped, and the reply says so."""
        if not self._pending:
            return Reply()
        block, line = self._open_block(), self.next_line
        self.cancel()
        return _error(
            f"<shell>:{line}:1: error: {block} has no 'end' before the input ended; "
            "nothing of it ran"
        )

    def _not_timed(self, words: list[str]) -> bool:
        """Whether ``run A B ...`` is not the language's ``run JOINT DIRECTION TIME``."""
        return words[1] not in self.arm.model.joint_names and words[2] not in DIRECTIONS

    def execute(self, text: str) -> Reply:
        """Check ``text`` against the arm as it is now, then run it."""
        source = Source("<shell>", text, self.next_line)
        first = self.next_line
        self.next_line += max(1, len(source.lines))
        self._typed = max(self._typed, self.next_line - 1)
        env = Env(self.resolver.poses, self.walker.procs, self.stepper.pace)
        result = check_source(
            source, model=self.arm.model, scene=self.scene,
            arm=self.arm, carried=self.side.scene_now() if self.scene else None,
            base_dir=self.base_dir, env=env,
        )  # fmt: skip
        if any(isinstance(s, Header) for s in result.program.statements):
            return _error("error: choose the arm, driver and scene when starting: "
                          "armkit --arm NAME --driver NAME shell")  # fmt: skip
        if not result.ok:
            return _error(ScriptCheckError(source, result.diagnostics).report())
        try:
            self.walker.walk(result.program.statements)
        except (ArmkitError, KeyboardInterrupt) as exc:
            self.arm.stop()
            ran = isinstance(exc, ScriptRunError)
            error = f"<shell>:{first}:1: error: {compact_numbers(str(exc))}"
            return _error(error if ran else "stopped")
        self.teaching.record(text)
        return Reply()

    def jog(self, keys: Iterable[str], step: float, show: Callable[[str], None]) -> None:
        """Jog with each key of ``keys`` until ``q``, Enter or end of input, calling
        ``show`` with each message and the status after each key; record the result."""
        jog = Jog(self.arm, step)
        show(self.status())
        for key in keys:
            if key in ("q", "\n", "\r", "\x04", ""):
                break
            message = jog.key(key, self._free_name())
            if jog.saved:
                name, q = jog.saved[-1]
                self.resolver.poses[name] = JointPose(q)
            if message:
                show(message)
            show(self.status())
        self.teaching.lines += jog.finish()

    def status(self) -> str:
        """One line: joint angles [deg] and the gripper point [mm]."""
        x, y, z, pitch = self.arm.position()
        angles = " ".join(f"{n[:5]} {a:+.1f}" for n, a in self.arm.angles().items())
        return f"{angles} | x {x:.0f} y {y:.0f} z {z:.0f} mm pitch {pitch:.0f}"

    def _free_name(self) -> str:
        k = 1
        while f"p{k}" in self.resolver.poses:
            k += 1
        return f"p{k}"

    def where(self) -> str:
        """The gripper point and joint angles now."""
        x, y, z, pitch = self.arm.position()
        angles = "  ".join(f"{n} {a:.2f}" for n, a in self.arm.angles().items())
        return f"gripper at x {x:.1f} y {y:.1f} z {z:.1f} mm, pitch {pitch:.1f} deg\njoints {angles} deg"

    def _shell_word(self, words: list[str]) -> Reply:
        word, args = words[0], words[1:]
        if wrong := _wrong_count(word, args):
            return _error(wrong)
        if word in ("quit", "exit"):
            return Reply(self._torque(True).text if self.limp else "", quit=True)
        if word in ("limp", "hold"):
            return self._torque(word == "hold")
        if word == "where":
            return Reply(self.where())
        if word == "poses":
            poses = self.resolver.poses.items()
            lines = [f"pose {n} = {'?' if p is None else p.describe()}" for n, p in poses]
            return Reply("\n".join(lines) or "no poses yet")
        if word == "help":
            if not args:
                return Reply(HELP)
            return Reply(usage_of(args[0]) or f"no command {args[0]!r}; type help")
        if word == "jog":
            return _error(LIMP) if self.limp else self._jog_word(args)
        return self._save(args[0]) if word == "save" else self._write(args[0])

    def _jog_word(self, args: list[str]) -> Reply:
        try:
            step = float(args[0]) if args else 5.0
        except ValueError:
            return _error(f"error: jog takes a step in degrees, got {args[0]!r}")
        if not 0.1 <= step <= 45.0:
            return _error(f"error: the jog step must be in 0.1..45 deg, got {step:g}")
        return Reply(jog=step)

    def _torque(self, on: bool) -> Reply:
        """``limp`` (``on`` False) or ``hold``; ``hold`` records where the hand left the arm."""
        if on != self.limp:
            return Reply("the arm holds already" if on else "the arm is limp already")
        try:
            torque(self.arm, on)
        except ArmkitError as exc:
            return _error(f"error: {exc}")
        self.limp = not on
        if not on:
            return Reply(
                "limp: torque off, move the arm by hand (support it); save NAME, then hold"
            )
        self.teaching.lines.append(f"{joints_line(pose_now(self.arm))}   # moved by hand")
        return Reply("hold: torque on, the arm holds where it is")

    def _save(self, name: str) -> Reply:
        if not Token("word", name, 1).is_name or name in RESERVED:
            return _error(
                f"error: {name!r} cannot name a pose (a letter, then letters, digits, _ or -; "
                "not a word of the language)"
            )
        q = pose_now(self.arm)
        self.resolver.poses[name] = JointPose(q)
        return Reply("saved: " + self.teaching.save(name, q))

    def _write(self, name: str) -> Reply:
        path = (self.base_dir / name).expanduser()
        if path.is_dir():
            return _error(f"error: cannot write {path}: it is a directory; give a file name in it, such as {path / 'taught.arm'}")  # fmt: skip
        if not path.parent.is_dir():
            return _error(f"error: cannot write {path}: no folder {path.parent}")
        here = path.parent
        scene = None if self.scene is None else self._file_or_name(self.scene.label, here)
        arm = _arm_word(self.arm.model, here)
        try:
            write_atomic(path, replace(self.teaching, arm=arm, scene=scene).script(), durable=False)
        except OSError as exc:
            why = (exc.strerror or type(exc).__name__).lower()
            return _error(
                f"error: cannot write {path}: the folder {path.parent} does not take new "
                f"files ({why}); choose another folder"
            )
        return Reply(
            f"wrote {count(len(self.teaching.lines), 'line')} to {path}; "
            f"replay with: armkit run {name}"
        )

    def _run_file(self, name: str) -> Reply:
        path = (self.base_dir / name).expanduser()
        try:
            source = Source.read(path)
        except LimitError as exc:
            return _error(f"error: cannot run {path}: {_unreadable(exc)}")
        try:
            run_source(self.arm, source, scene=self.scene)
        except ScriptCheckError as exc:
            return _error(exc.report())
        except (ArmkitError, OSError, KeyboardInterrupt) as exc:
            self.arm.stop()
            return _error(f"error: {compact_numbers(str(exc))}")
        self.teaching.lines += [f"# ran {name}; it ended here:", joints_line(pose_now(self.arm))]
        return Reply(f"ran {name}")

    def _file_or_name(self, label: str, here: Path) -> str:
        """The scene ``label`` as a script in ``here`` finds it: a file the session read
        (next to where it started, or a path) by its path from ``here``; else the name of
        a shipped scene, as given."""
        for candidate in (self.base_dir / label, Path(label)):
            if candidate.is_file():
                return _path_from(candidate, here)
        return label


def _arm_word(model: ArmModel, here: Path) -> str:
    """The ``arm`` line's word for ``model`` in a script in ``here``: a shipped model's
    name, else its file (a .toml by its path from ``here``, where the checker looks for
    it; a URDF, which is read from where armkit runs, by its absolute path)."""
    source = model.source
    if source is None or (
        model.name in shipped_models() and load_model(model.name).source == source
    ):
        return model.name
    if source.suffix == ".toml":
        return _path_from(source, here)
    return str(source.resolve())


def _path_from(path: Path, here: Path) -> str:
    """``path`` from the folder ``here`` (relative where it can be, else absolute), with /."""
    try:
        return Path(os.path.relpath(path.resolve(), here.resolve())).as_posix()
    except ValueError:  # another drive (Windows)
        return str(path.resolve())


def _unreadable_line(line: str) -> tuple[int, str] | None:
    """(column, why) if a typed line cannot be read: longer than ``MAX_LINE_CHARS``, or
    bytes that are not UTF-8 (read as lone surrogates, ``Shell`` reads so)."""
    if len(line) > MAX_LINE_CHARS:
        return MAX_LINE_CHARS + 1, (
            f"a line longer than {MAX_LINE_CHARS} characters; break it into shorter lines"
        )
    bad = next((k for k, c in enumerate(line) if "\udc80" <= c <= "\udcff"), None)
    if bad is not None:
        byte = ord(line[bad]) - 0xDC00
        return bad + 1, f"not UTF-8 text (byte {byte:02x}); type or pipe UTF-8"
    return None


def _run_file(words: list[str]) -> bool:
    """Whether ``words`` are the shell's ``run FILE`` (the language's run takes three)."""
    return len(words) == 2 and words[0] == "run"


def _unreadable(exc: LimitError) -> str:
    """Why a script cannot be read, in words, and what to give instead."""
    why = exc.__cause__ or exc.__context__
    if isinstance(why, IsADirectoryError) or "is a directory" in exc.problem:
        return "it is a directory; give a script file (.arm) in it"
    if isinstance(why, FileNotFoundError):
        return "no such file; give a script file (.arm)"
    if isinstance(why, PermissionError):
        return "reading it is not allowed (permission denied)"
    if exc.line:  # not UTF-8, or a NUL
        return "it is not a text file (UTF-8); give a script file (.arm)"
    return exc.problem


def _wrong_count(word: str, args: list[str]) -> str:
    """'' if the shell word ``word`` may take ``args``, else the one-line error."""
    what = ARGUMENTS.get(word, "")
    optional = what.startswith("[")
    if len(args) <= bool(what) and (args or optional or not what):
        return ""
    got = repr(" ".join(args)) if args else "none"
    if not what:
        return f"error: {word} takes no argument, got {got}"
    most = "at most " if optional else ""
    return f"error: {word} takes {most}one {what.strip('[]')} ({word} {what}), got {got}"


def _depth_change(line: str) -> int:
    """+1 for a line opening a block (repeat, define), -1 for 'end', else 0."""
    try:
        tokens = tokenize(line)
    except LexError:
        return 0
    if not tokens:
        return 0
    first = tokens[0].text
    return 1 if first in ("repeat", "define") else -1 if first == "end" else 0
