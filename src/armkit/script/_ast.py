"""The parsed script: values, targets and statements (frozen dataclasses).

Values stay as written (number and unit, or a name) until they are resolved,
because a procedure's parameter gets its value only when it is called. Every
node keeps the line and column it came from, for messages.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property
from pathlib import Path
from typing import Literal

from .._input_limits import MAX_SCRIPT_BYTES, decode, read_limited
from ._units import Dim


@dataclass(frozen=True)
class Loc:
    """Where something was written: line and column, 1-based."""

    line: int
    col: int


@dataclass(frozen=True)
class Num:
    """A number as written; ``unit`` None means the default of where it is used."""

    value: float
    unit: str | None
    loc: Loc


@dataclass(frozen=True)
class Ref:
    """A name where a value is expected: a procedure parameter (``-name``: negated)."""

    name: str
    loc: Loc
    negate: bool = False


Value = Num | Ref


@dataclass(frozen=True)
class Quantity:
    """A value and the dimension it must have where it is used."""

    value: Value
    dim: Dim


@dataclass(frozen=True)
class XYZ:
    """``xyz X Y Z [pitch P]``: a gripper point [length] and approach pitch [angle]."""

    x: Value
    y: Value
    z: Value
    pitch: Value | None
    loc: Loc


@dataclass(frozen=True)
class JointList:
    """``joints A B C ...``: one angle per joint, in chain order."""

    angles: tuple[Value, ...]
    loc: Loc


@dataclass(frozen=True)
class PoseName:
    """A named pose (or a parameter holding one)."""

    name: str
    loc: Loc


@dataclass(frozen=True)
class Here:
    """``here``: where the arm is when the statement runs."""

    loc: Loc


TargetExpr = XYZ | JointList | PoseName | Here


@dataclass(frozen=True)
class Move:
    """``move TARGET`` (a joint move) or ``line TARGET`` (straight)."""

    target: TargetExpr
    straight: bool
    loc: Loc


@dataclass(frozen=True)
class Turn:
    """``turn JOINT ANGLE`` or ``turn JOINT by ANGLE``."""

    joint: str
    angle: Value
    relative: bool
    loc: Loc
    joint_loc: Loc


@dataclass(frozen=True)
class Grip:
    """``grip WIDTH`` or ``grip open|close``: width None with ``state`` set."""

    width: Value | None
    state: Literal["open", "close"] | None
    loc: Loc


@dataclass(frozen=True)
class Simple:
    """A statement with at most one value: ``home``, ``wait T``, ``speed S``, ``light on``.

    Attributes:
        command: ``home``, ``wait``, ``speed`` (percent: joint moves), ``tool-speed``
            (mm/s: straight lines), ``light``.
        value: its value (None for ``home`` and ``light``).
        flag: ``light``'s on (True) or off.
    """

    command: str
    value: Value | None
    loc: Loc
    flag: bool = False


@dataclass(frozen=True)
class RunMotor:
    """``run JOINT DIRECTION TIME``: the OWI's timed rotation (000's program mode)."""

    joint: str
    direction: int
    word: str
    seconds: Value
    loc: Loc
    joint_loc: Loc


@dataclass(frozen=True)
class PoseDef:
    """``pose NAME = TARGET``."""

    name: str
    target: TargetExpr
    loc: Loc


@dataclass(frozen=True)
class Header:
    """``arm NAME``, ``driver NAME [port PORT]`` or ``scene FILE``."""

    kind: Literal["arm", "driver", "scene"]
    value: str
    port: str | None
    loc: Loc
    value_loc: Loc


@dataclass(frozen=True)
class JobArg:
    """One argument of a job: a quantity, a target, a word or file as written, or
    True for a flag written."""

    name: str
    value: Quantity | TargetExpr | str | bool | tuple[PoseName, ...]
    loc: Loc


@dataclass(frozen=True)
class Job:
    """A job command (``pick``, ``draw`` ...) with its arguments by parameter name."""

    command: str
    args: tuple[JobArg, ...]
    loc: Loc


@dataclass(frozen=True)
class Repeat:
    """``repeat N`` ... ``end``."""

    count: Value
    body: tuple[Statement, ...]
    loc: Loc


@dataclass(frozen=True)
class Define:
    """``define NAME(P, ...)`` ... ``end``."""

    name: str
    params: tuple[str, ...]
    body: tuple[Statement, ...]
    loc: Loc


@dataclass(frozen=True)
class Call:
    """``NAME ARG ...``: a procedure call; each argument a number or a name."""

    name: str
    args: tuple[Num | PoseName, ...]
    loc: Loc


Statement = Move | Turn | Grip | Simple | RunMotor | PoseDef | Header | Job | Repeat | Define | Call


@dataclass(frozen=True)
class Program:
    """A parsed script: its statements and the source it came from.

    Attributes:
        broken: names of poses and procedures whose definition did not parse
            (their uses are not reported again).
    """

    statements: tuple[Statement, ...]
    source: Source
    broken: frozenset[str] = frozenset()


@dataclass(frozen=True)
class Source:
    """A script's text and the name to report it by (a path or ``<shell>``).

    Attributes:
        first_line: the number of its first line (the shell numbers its input on).
    """

    name: str
    text: str
    first_line: int = 1

    @classmethod
    def read(cls, path: str | Path) -> Source:
        """The script in the file ``path``, read within armkit's input limits (its size,
        UTF-8 or UTF-16 with a BOM, no NUL; see ``_input_limits``).

        Raises:
            LimitError: ``FILE: why`` or ``FILE:LINE:COL: why`` (an ``InputError``).
        """
        return cls(str(path), decode(read_limited(path, MAX_SCRIPT_BYTES, "script"), str(path)))

    @cached_property
    def lines(self) -> list[str]:
        """The lines, without their ends (split once: a message or a progress line
        looks one up for every statement)."""
        return self.text.splitlines()

    def line(self, number: int) -> str:
        """Line ``number`` (counted from ``first_line``), or '' outside the text."""
        lines = self.lines
        k = number - self.first_line
        return lines[k] if 0 <= k < len(lines) else ""
