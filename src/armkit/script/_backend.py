"""What a walker drives: the ``Backend`` protocol (``_stepper.Stepper``, which plans each
statement and folds the plan or carries it out), the ``Frame`` of a repeat or call being walked, and the run-time error."""

from __future__ import annotations

from collections.abc import Hashable
from contextlib import AbstractContextManager
from dataclasses import dataclass
from typing import Literal, Protocol

from .._errors import ScriptError
from ._ast import Loc, Statement
from ._diagnostics import collapse
from ._resolve import JointPose, Target


@dataclass(frozen=True)
class Frame:
    """A repeat iteration or a procedure call being walked."""

    kind: Literal["repeat", "call"]
    name: str
    loc: Loc
    iteration: int = 0
    count: int = 0

    def describe(self) -> str:
        """``repeat iteration 3 of 5 (line 8)`` or ``in dip called at line 20``."""
        if self.kind == "repeat" and self.loc.line == 0:
            return f"run {self.iteration} of {self.count} (--repeat)"
        if self.kind == "repeat":
            return f"repeat iteration {self.iteration} of {self.count} (line {self.loc.line})"
        return f"in {self.name} called at line {self.loc.line}"


class Backend(Protocol):
    """What executes (or simulates) the statements; every quantity in SI."""

    def begin(self, stmt: Statement, frames: tuple[Frame, ...]) -> None: ...
    def here(self) -> JointPose | None: ...
    def move(self, target: Target | None, straight: bool) -> None: ...
    def turn(self, joint: str, angle: float | None, relative: bool) -> None: ...
    def grip(self, width: float | None) -> None: ...
    def home(self) -> None: ...
    def wait(self, seconds: float | None) -> None: ...
    def speed(self, value: float | None, tool: bool) -> None: ...
    def light(self, on: bool) -> None: ...
    def run_motor(self, joint: str, direction: int, seconds: float | None) -> None: ...
    def job(self, command: str, args: dict[str, object]) -> None: ...
    def snapshot(self) -> Hashable | None: ...
    def elapsed(self) -> float: ...
    def skip(self, iterations: int, seconds: float, loc: Loc) -> None: ...
    def blind(self) -> AbstractContextManager[None]: ...
    def lose_track(self) -> None: ...


class ScriptRunError(ScriptError):
    """A statement failed while the script ran: names the line and the repeat iteration.

    Attributes:
        loc: the statement's place.  frames: the repeats and calls it ran in.
        message: what failed, without the place and the frames.
    """

    def __init__(self, source: str, loc: Loc, message: str, frames: tuple[Frame, ...]) -> None:
        context = "; ".join(collapse([f.describe() for f in reversed(frames)]))
        text = f"{source}:{loc.line}:{loc.col}: {message}"
        super().__init__(text + (f" ({context})" if context else ""))
        self.loc, self.frames, self.message = loc, frames, message
