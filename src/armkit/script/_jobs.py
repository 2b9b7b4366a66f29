"""The job commands (``pick``, ``place``, ``move-item``, ``rotate-cube``, ``stack``,
``search``, ``draw``, ``play``): one table entry each, its arguments and the
function that does it.

Adding a job is one entry in ``JOBS``: the parameters (how they are written and
checked), ``call``, the function that does it (by reference: a small function here
that imports it when the job runs), and ``check``, the function ``armkit check``
calls with the scene and the same arguments (``_job_checks``: the job's own argument
checks, so what check passes the job takes).
The function is called as ``function(arm, scene, **arguments)`` with

- ``where`` arguments: a scene object's or place's name (str), or a gripper
  point (x, y, z) [mm], as the tasks take it (a pose or ``xyz`` target; joint
  poses through FK);
- ``object``: a scene name (str); ``objects``: a tuple of them;
- ``file``: a ``pathlib.Path`` (relative paths are relative to the script);
- ``choice``: the word; ``flag``: True when its keyword is written (it takes
  no value: ``draw square.svg fit``); ``angle`` [rad]; ``length`` [m]; ``percent`` as a
  fraction; ``count`` an int. Optional arguments not written are not passed.

``place`` puts down the cube the script's ``pick`` took: the runner passes it as
``cube`` (the checker refuses a ``place`` with nothing picked).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any, Literal

import numpy as np

from .._errors import ScriptError
from .._inputs import is_number
from . import _job_checks as checks
from ._units import Dim

ParamKind = Literal[
    "where", "object", "objects", "file", "choice", "flag", "angle", "length", "percent", "count"
]
QUANTITY_KINDS: dict[str, Dim] = {
    "angle": "angle",
    "length": "length",
    "percent": "percent",
    "count": "count",
}


@dataclass(frozen=True)
class JobParam:
    """One parameter of a job.

    Attributes:
        name: the keyword argument passed to the function.
        kind: how it is written and checked (see the module doc).
        keyword: the word written before it (``to``), or None for a positional one.
        required: must be written.
        choices: the words of a ``choice``, or the suffixes a ``file`` may have.
        hint: said when what is written cannot be this argument (how to write it).
    """

    name: str
    kind: ParamKind
    keyword: str | None = None
    required: bool = True
    choices: tuple[str, ...] = ()
    hint: str = ""

    @property
    def usage(self) -> str:
        """How it is written, e.g. ``[to WHERE]``."""
        shown = "|".join(self.choices) if self.kind == "choice" else self.name.upper()
        if self.kind == "objects":
            shown += " ..."
        if self.kind == "flag":
            return f"[{self.keyword}]"
        text = f"{self.keyword} {shown}" if self.keyword else shown
        return text if self.required else f"[{text}]"


@dataclass(frozen=True)
class JobSpec:
    """A job: its parameters, the function that runs it, one line of help, the
    function that checks its arguments (called as ``function(scene, **arguments)``;
    None: none), words it refuses with why
    (``refused``: word -> message), and whether the function plans the job whole
    before it moves and can plan it from a model and joints alone (``plans``: given an
    ``armkit.tasks.Start``), so that ``armkit check`` plans it too; ``check_plans``: its
    check plans it, given the arm as the check knows it (``arm=tasks.Start``)."""

    params: tuple[JobParam, ...]
    call: Callable[..., object]
    help: str
    check: Callable[..., object] | None = None
    refused: tuple[tuple[str, str], ...] = ()
    plans: bool = False
    check_plans: bool = False

    def usage(self, command: str) -> str:
        """``move-item ITEM to WHERE``."""
        return " ".join([command, *(p.usage for p in self.params)])


DRAW_SUFFIXES = (".svg", ".gcode", ".nc", ".ngc", ".gc")
PLAY_SUFFIXES = (".mid", ".midi", ".rtttl", ".txt")


# The jobs' functions, each imported when the job runs (``armkit --help`` and the
# checker's parse load none of them).


def _pick(*args: Any, **kwargs: Any) -> object:
    from ..tasks import pick

    return pick(*args, **kwargs)


def _place(*args: Any, **kwargs: Any) -> object:
    from ..tasks import place

    return place(*args, **kwargs)


def _move_item(*args: Any, **kwargs: Any) -> object:
    from ..tasks import move_item

    return move_item(*args, **kwargs)


def _rotate_cube(*args: Any, **kwargs: Any) -> object:
    from ..tasks import rotate_cube

    return rotate_cube(*args, **kwargs)


def _stack(*args: Any, **kwargs: Any) -> object:
    from ..tasks import stack

    return stack(*args, **kwargs)


def _search(*args: Any, **kwargs: Any) -> object:
    from ..tasks import search

    return search(*args, **kwargs)


def _draw(*args: Any, **kwargs: Any) -> object:
    from ..drawing import draw

    return draw(*args, **kwargs)


def _play(*args: Any, **kwargs: Any) -> object:
    from ..music import play

    return play(*args, **kwargs)


PICK_HINT = (
    "pick takes a cube of the scene by its name (pick red); an item known only by "
    "its point is carried with move-item xyz X Y Z to WHERE"
)
NOTHING_PICKED = (
    "place puts down the cube the script picked, and no cube is picked here; "
    "write 'pick CUBE' before it"
)
STACK_ON = (
    "stack takes no 'on WHERE': the first cube named stays where it is and the others "
    "go on it (stack red green blue puts green on red, blue on green)"
)

JOBS: dict[str, JobSpec] = {
    "pick": JobSpec(
        (JobParam("cube", "object", hint=PICK_HINT),),
        _pick,
        "pick up a cube of the scene (by name) and stay above it",
        check=checks.pick,
        plans=True,
    ),
    "place": JobSpec(
        (JobParam("to", "where"),),
        _place,
        "put the picked cube down at a scene place, board[ROW,COL], a cube, a container, "
        "a pose or an xyz point",
        check=checks.place,
        plans=True,
    ),
    "move-item": JobSpec(
        (JobParam("item", "where"), JobParam("to", "where", keyword="to")),
        _move_item,
        "000: pick an item up, lift it, carry it and put it down",
        check=checks.move_item,
        plans=True,
    ),
    "rotate-cube": JobSpec(
        (
            JobParam("cube", "object"),
            JobParam("direction", "choice", required=False, choices=("forward", "backward")),
        ),
        _rotate_cube,
        "001: turn a cube onto its side (forward) or back up (backward) where it stands",
        check=checks.rotate_cube,
        plans=True,
    ),
    "stack": JobSpec(
        (JobParam("cubes", "objects"),),
        _stack,
        "001: turn every cube in place, then stack them on the first, each on the one before",
        check=checks.stack,
        plans=True,
        refused=(("on", STACK_ON),),
    ),
    "search": JobSpec(
        (
            JobParam("start", "angle", keyword="from", required=False),
            JobParam("stop", "angle", keyword="to", required=False),
            JobParam("step", "angle", keyword="step", required=False),
            JobParam("into", "object", keyword="into", required=False),
        ),
        _search,
        "002: scan with the distance sensor, pick up what is found, drop it in a container",
        check=checks.search,
    ),
    "draw": JobSpec(
        (
            JobParam("file", "file", choices=DRAW_SUFFIXES),
            JobParam("sheet", "object", keyword="on", required=False),
            JobParam("pen", "object", keyword="with", required=False),
            JobParam("fit", "flag", keyword="fit", required=False),
        ),
        _draw,
        "draw an SVG or G-code file on a sheet at its real size (fit: scaled to the sheet), "
        "picking the pen up and putting it back",
        check=checks.draw,
        check_plans=True,
    ),
    "play": JobSpec(
        (
            JobParam("file", "file", choices=PLAY_SUFFIXES),
            JobParam("on", "object", keyword="on", required=False),
            JobParam("tempo", "percent", keyword="tempo", required=False),
            JobParam("transpose", "count", keyword="transpose", required=False),
        ),
        _play,
        "play a MIDI, RTTTL or note-list tune on the scene's instrument",
        check=checks.play,
        check_plans=True,
    ),
}


def job_keywords() -> set[str]:
    """Every word written before a job argument."""
    return {p.keyword for spec in JOBS.values() for p in spec.params if p.keyword}


def job_function(command: str) -> Callable[..., object]:
    """The function that runs ``command``."""
    return JOBS[command].call


def job_check(command: str) -> Callable[..., object] | None:
    """The function that checks ``command``'s arguments (None: the job has none)."""
    return JOBS[command].check


def as_called(command: str, args: dict[str, object]) -> dict[str, object]:
    """The arguments as ``command``'s function (and its check) takes them, in mm and deg:
    a ``where`` point [m], shape (3,), as (x, y, z) [mm], an angle [rad] in degrees; the
    rest as they are."""
    angles = {p.name for p in JOBS[command].params if p.kind == "angle"}
    return {k: _in_deg(v) if k in angles else _in_mm(v) for k, v in args.items()}


def called_with(command: str, args: dict[str, object], held: str | None) -> dict[str, object]:
    """The keyword arguments ``command``'s function gets: ``as_called``, and for ``place``
    the cube the script's ``pick`` took, ``held`` (ScriptError if none was)."""
    called = as_called(command, args)
    if command != "place":
        return called
    if held is None:
        raise ScriptError(NOTHING_PICKED)
    return {"cube": held, **called}


def _in_deg(value: object) -> object:
    return math.degrees(value) if isinstance(value, float | int) and is_number(value) else value


def _in_mm(value: object) -> object:
    if isinstance(value, np.ndarray) and value.shape == (3,):
        return tuple(float(v) * 1000.0 for v in value)
    return value
