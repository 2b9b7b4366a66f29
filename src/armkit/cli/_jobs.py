"""The job sub-commands, built from the job specs (``armkit.jobs.JOBS``): each
parameter becomes a positional argument or an option with its unit, bounds and default
in its help, so the CLI and the script language take the same parameters in the same
units. A job module of the CLI (tasks, draw, play) adds its jobs with ``add_job`` and its
own handler (what it prints); ``add_commands`` adds every other job with ``run_job``,
so a job added to ``JOBS`` is an ``armkit`` command with no more code."""

from __future__ import annotations

import argparse
from collections.abc import Callable
from pathlib import Path
from typing import Any

from .._errors import InputError
from ..jobs import CLI_JOBS, JOBS, METAVAR, JobParam, JobSpec, as_function_gets, job_spec
from ._args import integer, number, percent
from ._watch import add_watch_options, watched_arm

Handler = Callable[[argparse.Namespace], int]
# the widest value a quantity takes where its spec names no bounds (the job refuses more)
WIDEST = {"angle": 360.0, "length": 100_000.0, "speed": 100_000.0, "time": 1e6, "percent": 1e6}


def add_commands(sub: argparse._SubParsersAction[Any]) -> None:
    """Add every job no other command module added, run by ``run_job``."""
    for name, spec in {**JOBS, **CLI_JOBS}.items():
        if name not in sub.choices and not spec.cli_forms:
            add_job(sub, name, run_job)


def add_job(
    sub: argparse._SubParsersAction[Any],
    name: str,
    handler: Handler,
    form: tuple[str, str, tuple[str, ...]] | None = None,
) -> argparse.ArgumentParser:
    """The sub-command of job ``name`` (with ``form``: its sub-command for one kind of file,
    named by the form's word), every parameter of its spec added; ``args.job`` names it."""
    spec = job_spec(name)
    word, text = (name, spec.help) if form is None else (form[0], f"{name} {form[1]}: {spec.help}")
    p: argparse.ArgumentParser = sub.add_parser(
        word, help=text.replace("%", "%%"), description=text + ".", epilog=spec.epilog or None
    )
    for param in spec.cli_params:
        _add_param(p, param)
    add_watch_options(p)
    p.set_defaults(func=handler, job=name, suffixes=form[2] if form else ())
    return p


def _add_param(p: argparse.ArgumentParser, param: JobParam) -> None:
    more: dict[str, Any] = {"help": param.described().replace("%", "%%")}
    if param.kind == "flag":
        p.add_argument(param.option or f"--{param.name}", dest=param.name, action="store_true", **more)  # fmt: skip
        return
    more["metavar"] = param.metavar or METAVAR.get(param.kind, param.name.upper())
    if param.kind == "choice":
        more.update(choices=param.choices, metavar=None)
    elif param.kind in WIDEST or param.kind == "count":
        more["type"] = _type_of(param)
    if param.default is not None:
        more["default"] = param.default
    if param.option is not None:
        p.add_argument(param.option, dest=param.name, **more)
        return
    if param.kind == "objects":
        more["nargs"] = "+"
    elif not param.required or param.point or param.cli_optional:
        more["nargs"] = "?"
    p.add_argument(param.name, **more)
    if param.point:
        p.add_argument(param.point, nargs=3, type=number("mm", -1e5, 1e5), metavar=("X", "Y", "Z"), help=f"or a point [mm] instead of {more['metavar']} (default: none, {more['metavar']} names where)")  # fmt: skip


def _type_of(param: JobParam) -> Callable[[str], Any]:
    """The argparse type of a quantity: bounded, finite, in the parameter's unit."""
    if param.kind == "count":
        least = -1_000_000 if param.low is None else int(param.low)
        return integer("", least, 1_000_000 if param.high is None else int(param.high))
    wide = WIDEST[param.kind]
    low = -wide if param.low is None else param.low
    high = wide if param.high is None else param.high
    return percent(low, high) if param.kind == "percent" else number(param.unit, low, high)


def job_arguments(args: argparse.Namespace) -> dict[str, Any]:
    """The keyword arguments the job's function gets from the parsed command line, in its
    units (``armkit.jobs.as_function_gets``); InputError on a ``where`` given twice or not."""
    spec: JobSpec = job_spec(args.job)
    out: dict[str, Any] = {}
    for param in spec.cli_params:
        if not param.passed:
            continue
        value = getattr(args, param.name)
        if param.point:
            value = _where(args, param, value)
        elif param.kind == "file" and value is not None:
            value = Path(value)
        out[param.name] = as_function_gets(param.kind, value)
    return out


def _where(args: argparse.Namespace, param: JobParam, name: str | None) -> Any:
    """A name or the point of ``param.point`` [mm], exactly one of them."""
    point = getattr(args, (param.point or "").lstrip("-").replace("-", "_"))
    shown = param.name.upper()
    if name is not None and point is not None:
        raise InputError(f"'{args.job}' takes {shown} {name} or {param.point} X Y Z [mm], not both; drop one")  # fmt: skip
    if name is None and point is None:
        raise InputError(f"'{args.job}' needs {shown} <where> (a place, board[ROW,COL], cube or container) or {param.point} X Y Z [mm]")  # fmt: skip
    return name if name is not None else tuple(point)


def run_job(args: argparse.Namespace) -> int:
    """Any job: open the arm on the scene, do it, print what it returns (its lines)."""
    from ._scene import scene_of

    scene = scene_of(args)
    with watched_arm(args, scene) as arm:
        done = job_spec(args.job).call(arm, scene, **job_arguments(args))
    lines = getattr(done, "lines", None)
    if callable(lines):
        print("\n".join(lines()))
    elif done is not None:
        print(done)
    return 0
