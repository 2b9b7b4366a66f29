"""What a job is, as data: its parameters (kind, unit, default, bounds, how each surface
writes it) and the function that does it. ``_jobs.JOBS`` holds one ``JobSpec`` per job;
the script's statement (``_grammar.read_job``) and the CLI's sub-command
(``armkit.cli._jobs``) are both built from it, so they take the same parameters in the
same units with the same defaults.

One unit per kind of quantity, on both surfaces (``UNIT``), and what the job's function
gets (``as_function_gets``):

- ``angle``: degrees; ``length``: millimetres; ``speed``: a tool speed, mm/s;
  ``time``: seconds; ``count``: a whole number (the function gets them so);
- ``percent``: a percentage (``tempo 90%``; the function gets the fraction 0.9);
- ``where``: a scene object's or place's name, ``board[ROW,COL]``, or a point
  (x, y, z) [mm] (script: ``xyz X Y Z``/a pose; CLI: the option ``point``, ``--xyz``);
- ``object``/``objects``: scene names; ``file``: a path; ``choice``: one of ``choices``;
  ``flag``: present or not; ``text``: a word passed as it is (a port's name).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Literal

ParamKind = Literal[
    "where",
    "object",
    "objects",
    "file",
    "choice",
    "flag",
    "text",
    "angle",
    "length",
    "speed",
    "time",
    "percent",
    "count",
]
Surface = Literal["both", "cli", "script"]

# the unit each kind of quantity is written in, on the CLI and in scripts alike
UNIT: dict[str, str] = {
    "angle": "deg",
    "length": "mm",
    "speed": "mm/s",
    "time": "s",
    "percent": "%",
    "count": "",
}
METAVAR: dict[str, str] = {
    "angle": "DEG",
    "length": "MM",
    "speed": "MM_S",
    "time": "S",
    "percent": "PERCENT",
    "count": "N",
}


@dataclass(frozen=True)
class JobParam:
    """One parameter of a job.

    Attributes:
        name: the keyword argument passed to the function.
        kind: how it is written and checked (see the module doc; its unit: ``UNIT``).
        keyword: the word written before it in a script (``to``), or None for a
            positional one.
        required: must be written.
        choices: the words of a ``choice``, or the suffixes a ``file`` may have.
        hint: said when what is written cannot be this argument (how to write it).
        help: what it is, for ``--help`` and the docs (its unit and default are added).
        option: the CLI's option (``--from``), or None: the CLI takes it positionally,
            in the order of the spec.
        default: its value when not written, in its unit (shown by ``--help``; the CLI
            passes it, a script leaves it to the function, whose default is the same:
            tests/script/test_job_spec.py holds them equal).
        surface: where it is written: ``both``, only the ``cli`` (options of the command
            itself, such as ``--dry-run``) or only the ``script``.
        low, high: the CLI's bounds in its unit (None: any finite number).
        point: for a ``where``: the CLI option that gives a point instead (``--xyz``).
        metavar: its name in the CLI's usage ('' : from its name or unit).
        passed: the CLI passes it to the function (False: the command reads it itself,
            as ``--wav``).
        cli_optional: the CLI may leave it out though a script must write it (``play
            --calibrate OUT`` needs no score).
    """

    name: str
    kind: ParamKind
    keyword: str | None = None
    required: bool = True
    choices: tuple[str, ...] = ()
    hint: str = ""
    help: str = ""
    option: str | None = None
    default: float | int | str | None = None
    surface: Surface = "both"
    low: float | None = None
    high: float | None = None
    point: str | None = None
    metavar: str = ""
    passed: bool = True
    cli_optional: bool = False

    @property
    def unit(self) -> str:
        """Its unit ('' for names, files, counts)."""
        return UNIT.get(self.kind, "")

    @property
    def usage(self) -> str:
        """How a script writes it, e.g. ``[to WHERE]``."""
        shown = "|".join(self.choices) if self.kind == "choice" else self.name.upper()
        if self.kind == "objects":
            shown += " ..."
        if self.kind == "flag":
            return f"[{self.keyword}]"
        text = f"{self.keyword} {shown}" if self.keyword else shown
        return text if self.required else f"[{text}]"

    def described(self) -> str:
        """Its help with unit, bounds and default: 'first scan angle [deg], 0..180
        (default 30)' (a help that speaks of its default itself keeps its words)."""
        text = self.help
        if self.unit:
            text += f" [{self.unit}]"
        if self.low is not None and self.high is not None:
            text += f", {self.low:g}..{self.high:g}"
        if self.kind == "flag" or "default" in self.help:
            return text
        if self.default is None:
            return text + " (default: none)"
        shown = f"{self.default:g}" if isinstance(self.default, float) else self.default
        return text + f" (default {shown})"


@dataclass(frozen=True)
class JobSpec:
    """A job: its parameters, the function that runs it, one line of help, the
    function that checks its arguments (called as ``function(scene, **arguments)``;
    None: none), words it refuses with why
    (``refused``: word -> message), and whether the function plans the job whole
    before it moves from a ``Start`` alone (``plans``: given an ``armkit.arm.Start``, a
    task), so that check and run plan it alike (``script._job_plans``).

    The CLI's sub-command is built from the same spec (``armkit.cli._jobs``):
    ``epilog`` is its ``--help``'s closing paragraph; ``cli_forms``, if any, make it
    one sub-command per kind of file (``(word, what, suffixes)``: ``draw svg FILE``)."""

    parameters: tuple[JobParam, ...]
    call: Callable[..., object]
    help: str
    check: Callable[..., object] | None = None
    refused: tuple[tuple[str, str], ...] = ()
    plans: bool = False
    epilog: str = ""
    cli_forms: tuple[tuple[str, str, tuple[str, ...]], ...] = ()

    @property
    def params(self) -> tuple[JobParam, ...]:
        """The parameters a script writes."""
        return tuple(p for p in self.parameters if p.surface != "cli")

    @property
    def cli_params(self) -> tuple[JobParam, ...]:
        """The parameters the CLI's command takes."""
        return tuple(p for p in self.parameters if p.surface != "script")

    def usage(self, command: str) -> str:
        """``move-item ITEM to WHERE``."""
        return " ".join([command, *(p.usage for p in self.params)])


def as_function_gets(kind: str, value: object) -> object:
    """A value written in ``kind``'s unit (``UNIT``) as the job's function takes it:
    a percentage as a fraction, the choice ``none`` as None, the rest as written."""
    if kind == "percent" and isinstance(value, int | float):
        return value / 100.0
    if kind == "choice" and value == "none":
        return None
    return value
