"""The jobs (``pick``, ``place``, ``move-item``, ``rotate-cube``, ``stack``, ``search``,
``reach``, ``draw``, ``play``): one ``JobSpec`` each (``armkit.jobs``), from which both the
script's statement and the CLI's sub-command (``armkit.cli._jobs``) are built.

Adding a job is one entry in ``JOBS``: the parameters (how each surface writes them,
their units, defaults and bounds), ``call``, the function that does it (by reference:
a small function here that imports it when the job runs), and ``check``, the function
``armkit check`` calls with the scene and the same arguments (``_job_checks``: the
job's own argument checks, so what check passes the job takes).
The function is called as ``function(arm, scene, **arguments)`` with

- ``where`` arguments: a scene object's or place's name (str), or a gripper
  point (x, y, z) [mm], as the tasks take it (a pose or ``xyz`` target; joint
  poses through FK);
- ``object``: a scene name (str); ``objects``: a tuple of them;
- ``file``: a ``pathlib.Path`` (relative paths are relative to the script);
- ``choice``: the word (``none``: None); ``flag``: True when its keyword is written (it
  takes no value: ``draw square.svg fit``); ``angle`` [deg]; ``length`` [mm]; ``speed``
  [mm/s]; ``percent`` as a fraction; ``count`` an int. Optional arguments not written
  are not passed.

``place`` puts down the cube the script's ``pick`` took: the runner passes it as
``cube`` (the checker refuses a ``place`` with nothing picked).
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np

from .._errors import ScriptError
from .._inputs import is_number
from ..jobs import CLI_JOBS as CLI_JOBS
from ..jobs import JOBS as JOBS
from ..jobs import NOTHING_PICKED as NOTHING_PICKED
from ..jobs import JobParam as JobParam
from ..jobs import JobSpec as JobSpec
from ..jobs import job_spec as job_spec
from ._units import Dim

QUANTITY_KINDS: dict[str, Dim] = {
    "angle": "angle",
    "length": "length",
    "speed": "speed",
    "time": "time",
    "percent": "percent",
    "count": "count",
}


def job_keywords() -> set[str]:
    """Every word written before a job argument."""
    return {p.keyword for spec in JOBS.values() for p in spec.params if p.keyword}


def job_check(command: str) -> Callable[..., object] | None:
    """The function that checks ``command``'s arguments (None: the job has none)."""
    return JOBS[command].check


# script values are SI (``_units``): the factor to the unit the job's function takes
FROM_SI = {"angle": 180.0 / math.pi, "length": 1e3, "speed": 1e3}


def as_called(command: str, args: dict[str, object]) -> dict[str, object]:
    """The arguments as ``command``'s function (and its check) takes them, in mm and deg
    (``armkit.jobs.UNIT``): a ``where`` point [m], shape (3,), as (x, y, z) [mm], an angle
    [rad] in degrees, a length [m] in mm, a speed [m/s] in mm/s; the rest as they are."""
    kinds = {p.name: p.kind for p in JOBS[command].params}
    return {k: _from_si(kinds.get(k, ""), v) for k, v in args.items()}


def called_with(command: str, args: dict[str, object], held: str | None) -> dict[str, object]:
    """The keyword arguments ``command``'s function gets: ``as_called``, and for ``place``
    the cube the script's ``pick`` took, ``held`` (ScriptError if none was)."""
    called = as_called(command, args)
    if command != "place":
        return called
    if held is None:
        raise ScriptError(NOTHING_PICKED)
    return {"cube": held, **called}


def _from_si(kind: str, value: object) -> object:
    if kind in FROM_SI and isinstance(value, float | int) and is_number(value):
        return float(value) * FROM_SI[kind]
    if isinstance(value, np.ndarray) and value.shape == (3,):
        return tuple(float(v) * 1000.0 for v in value)
    return value
