"""``armkit --scene FILE draw svg FILE`` and ``draw gcode FILE``: a picture drawn on
the scene's sheet with its pen (picked up from its stand and put back), in mm and deg."""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import TYPE_CHECKING, Any

from .._errors import InputError
from .._progress import Progress
from ..jobs import JOBS
from ._jobs import add_job, job_arguments
from ._watch import watched_arm

if TYPE_CHECKING:
    import numpy as np
    from numpy.typing import ArrayLike, NDArray


def add_file_commands(shapes: argparse._SubParsersAction[Any]) -> None:
    """Add ``draw svg`` and ``draw gcode`` to the draw command's sub-commands (from the
    job spec, ``armkit.jobs.JOBS["draw"]``: one sub-command per kind of file)."""
    for form in JOBS["draw"].cli_forms:
        add_job(shapes, "draw", _run, form)


def add_plane_option(p: argparse.ArgumentParser) -> None:
    """``--normal NX NY NZ``: the plane of a circle or rectangle (default: horizontal)."""
    p.add_argument(
        "--normal", nargs=3, type=float, metavar=("NX", "NY", "NZ"),
        help="the shape's plane by its normal (default 0 0 1, horizontal; 1 0 0: a wall "
        "facing the arm); x and width turn with it",
    )  # fmt: skip


def in_plane(
    points: NDArray[np.float64], center: ArrayLike, normal: list[float] | None
) -> NDArray[np.float64]:
    """Points, shape (N, 3), of a horizontal shape about ``center`` (same units) turned so
    that its plane's normal is ``normal`` (None: as they are); InputError if it is 0."""
    import numpy as np

    if normal is None:
        return points
    n = np.asarray(normal, dtype=np.float64)
    length = float(np.linalg.norm(n))
    if not (np.all(np.isfinite(n)) and length > 1e-9):
        raise InputError(
            f"--normal must be a non-zero direction, got {' '.join(f'{v:g}' for v in n)}"
        )
    n = n / length
    z = np.array([0.0, 0.0, 1.0])
    axis, c = np.cross(z, n), float(z @ n)
    if float(np.linalg.norm(axis)) < 1e-12:
        R = np.eye(3) if c > 0 else np.diag([1.0, -1.0, -1.0])
    else:
        K = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
        R = np.eye(3) + K + K @ K / (1.0 + c)
    o = np.asarray(center, dtype=np.float64)
    out: NDArray[np.float64] = (points - o) @ R.T + o
    return out


def _run(args: argparse.Namespace) -> int:
    from ..drawing import DrawingError, DrawOptions, check_picture_path, draw
    from ._scene import scene_of

    path = Path(args.file)
    if path.suffix.lower() not in args.suffixes:
        raise DrawingError(f"'draw {args.shape}' takes {' '.join(args.suffixes)} files", file=str(path))  # fmt: skip
    if not path.is_file():
        raise DrawingError("no such file", file=str(path))
    for option, out in (("--preview", args.preview), ("--result", args.result)):
        if out is not None:
            check_picture_path(out, option)
    scene = scene_of(args)
    opts = DrawOptions(
        tolerance=args.tolerance, margin=args.margin, pen_up=args.pen_up,
        pitch=args.pitch, speed=args.speed, held=args.held,
    )  # fmt: skip
    report = _Report(args.dry_run)
    with watched_arm(args, scene) as arm, report:
        job = draw(
            arm, scene, **job_arguments(args), options=opts, dry_run=args.dry_run,
            progress=report,
        )  # fmt: skip
    for line in job.lines()[report.printed :]:
        print(line)
    for what, out in (("preview", args.preview), ("result", args.result)):
        if out is not None and (what == "preview" or job.trace is not None):
            print(f"{what}: {out}")
    return 0


class _Report:
    """The plan's lines as soon as it is planned (before anything moves), then the
    strokes drawn so far on stderr (``armkit._progress``)."""

    def __init__(self, dry_run: bool) -> None:
        self.dry_run = dry_run
        self.printed = 0  # lines of ``job.lines()`` printed
        self.bar: Progress | None = None

    def __call__(self, job: Any, strokes: int) -> None:
        if self.printed == 0:
            lines = job.lines()
            print("\n".join(lines), flush=True)
            self.printed = len(lines)
        if self.bar is None and not self.dry_run:
            total = sum(1 for s in job.segments if getattr(s, "draws", False))
            self.bar = Progress(f"drawing {Path(job.plan.source).name}", total, "strokes")
        if self.bar is not None:
            self.bar.update(strokes)

    def __enter__(self) -> _Report:
        return self

    def __exit__(self, *exc: object) -> None:
        if self.bar is not None:
            self.bar.close()
