"""``armkit --scene FILE draw svg FILE`` and ``draw gcode FILE``: a picture drawn on
the scene's sheet with its pen (picked up from its stand and put back), in mm and deg."""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import TYPE_CHECKING, Any

from .._errors import InputError
from .._progress import Progress
from ._args import number
from ._watch import add_watch_options, watched_arm

if TYPE_CHECKING:
    import numpy as np
    from numpy.typing import ArrayLike, NDArray

EPILOG = (
    "Needs --scene FILE|NAME before 'draw' (a scene with a sheet and a pen, e.g. 'drawing'). "
    "The whole job is planned first (the file read at its real size, or scaled to the sheet "
    "with --fit, placed on the sheet, cut to the arm's "
    "reach with a note saying what was cut, every move checked); nothing moves on a bad "
    "file, name or output path. On a simulated arm, what the pen drew is measured."
)


def add_file_commands(shapes: argparse._SubParsersAction[Any]) -> None:
    """Add ``draw svg`` and ``draw gcode`` to the draw command's sub-commands."""
    for kind, text in (("svg", "an SVG file"), ("gcode", "a G-code file (.gcode .nc .ngc)")):
        p = shapes.add_parser(
            kind, help=f"draw {text} on the scene's sheet with its pen", epilog=EPILOG
        )
        p.add_argument("file", metavar="FILE", help=text)
        _options(p)
        p.set_defaults(func=_run, kind=kind)


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


def _options(p: argparse.ArgumentParser) -> None:
    p.add_argument("--sheet", metavar="NAME", help="the scene's sheet (default: its only one)")
    p.add_argument("--pen", metavar="NAME", help="the scene's pen (default: its only one)")
    p.add_argument(
        "--held",
        action="store_true",
        help="the pen is in the gripper already (on the simulator: taken to be, the stand's pen not used)",
    )
    p.add_argument(
        "--fit",
        action="store_true",
        help="scale the drawing to fill the sheet inside the margins (default: the file's "
        "real size from its units, viewBox and width/height, centred on the sheet)",
    )
    p.add_argument("--preview", metavar="PNG", help="draw the plan to this picture, then move")
    p.add_argument("--result", metavar="PNG", help="simulated arms: picture what was drawn")
    p.add_argument("--dry-run", action="store_true", help="plan (and --preview) only; no motion")
    mm = number("mm", 0.001, 5.0)
    p.add_argument("--tolerance", type=mm, default=0.1, metavar="MM", help="curves flattened within this [mm], 0.001..5 (default 0.1)")  # fmt: skip
    p.add_argument("--margin", type=number("mm", 0.0, 100.0), default=10.0, metavar="MM", help="blank border on the sheet [mm] (default 10)")  # fmt: skip
    p.add_argument("--pen-up", type=number("mm", 1.0, 100.0), default=10.0, metavar="MM", help="pen height above the paper between strokes [mm] (default 10)")  # fmt: skip
    p.add_argument("--pitch", type=number("deg", -90.0, 0.0), default=-60.0, metavar="DEG", help="pen angle above the horizontal while drawing [deg] (default -60)")  # fmt: skip
    p.add_argument("--speed", type=number("mm/s", 1.0, 500.0), default=30.0, metavar="MM_S", help="pen speed along lines [mm/s] (default 30)")  # fmt: skip
    add_watch_options(p)


def _run(args: argparse.Namespace) -> int:
    from ..drawing import DrawingError, DrawOptions, check_picture_path, draw
    from ._scene import scene_of

    path = Path(args.file)
    suffix = path.suffix.lower()
    wanted = (".svg",) if args.kind == "svg" else (".gcode", ".nc", ".ngc", ".gc", ".g", ".tap")
    if suffix not in wanted:
        raise DrawingError(f"'draw {args.kind}' takes {' '.join(wanted)} files", file=str(path))
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
            arm, scene, path, args.sheet, args.pen, options=opts, fit=args.fit,
            preview=args.preview, result=args.result, dry_run=args.dry_run,
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
