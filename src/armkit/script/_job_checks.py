"""Each job's argument checks as ``armkit check`` makes them: the checks the job's
own function (``armkit.tasks``, ``armkit.drawing``, ``armkit.music``) makes before
it plans, called with the script's scene and the arguments the job will get
(``_jobs.as_called``), so a script that passes its check does not stop half-way
on an argument. No range or rule is written here a second time.

Each function is ``check(scene, **arguments)`` (``JobSpec.check``); a refusal is a
``JobArgProblem`` naming the arguments it is about (the checker points at the first
one written).
"""

from __future__ import annotations

import inspect
from collections.abc import Iterator, Sequence
from contextlib import contextmanager
from pathlib import Path

from .._errors import ArmkitError, InputError
from ..scene import Scene


class JobArgProblem(InputError):
    """A job's argument its function would refuse; ``names``: the arguments it is about."""

    def __init__(self, names: tuple[str, ...], message: str) -> None:
        super().__init__(message)
        self.names = names


@contextmanager
def _about(*names: str) -> Iterator[None]:
    try:
        yield
    except (ArmkitError, ValueError) as exc:
        raise JobArgProblem(names, str(exc)) from None


def check_pick(scene: Scene, cube: str) -> None:
    """``tasks.pick``: a cube of the scene."""
    with _about("cube"):
        scene.cube(cube)


def check_place(scene: Scene, to: str | Sequence[float]) -> None:
    """``tasks.place``: where to, as ``tasks.resolve`` reads it."""
    from ..tasks import resolve

    with _about("to"):
        resolve(scene, to)


def check_move_item(scene: Scene, item: str | Sequence[float], to: str | Sequence[float]) -> None:
    """``tasks.move_item``: a cube of the scene (or a point) and where to."""
    from ..tasks import resolve

    with _about("item"):
        if isinstance(item, str):
            scene.cube(item)
        else:
            resolve(scene, item)
    with _about("to"):
        resolve(scene, to)


def check_rotate_cube(scene: Scene, cube: str, direction: str = "forward") -> None:
    """``tasks.rotate_cube``: a cube of the scene (the direction is a choice the
    grammar reads)."""
    with _about("cube"):
        scene.cube(cube)


def check_stack(scene: Scene, cubes: Sequence[str]) -> None:
    """``tasks.stack``: two or more different cubes of the scene."""
    from ..tasks import stack_names

    with _about("cubes"):
        for name in stack_names(cubes):
            scene.cube(name)


def check_search(
    scene: Scene,
    start: float | None = None,
    stop: float | None = None,
    step: float | None = None,
    into: str | None = None,
) -> None:
    """``tasks.search``: its scan angles (the job's defaults for those not written)
    and the container."""
    from ..tasks import check_angles, only_container
    from ..tasks import search as job

    default = {k: p.default for k, p in inspect.signature(job).parameters.items()}
    with _about("start", "stop", "step"):
        check_angles(
            default["start"] if start is None else start,
            default["stop"] if stop is None else stop,
            default["step"] if step is None else step,
        )
    with _about("into"):
        scene.container(into or only_container(scene))


def check_draw(
    scene: Scene, file: Path, sheet: str | None = None, pen: str | None = None, fit: bool = False
) -> None:
    """``drawing.draw``: the sheet and the pen of the scene, then the file planned on the
    sheet as the job plans it before it moves (``drawing.plan_on_sheet``: a file with
    nothing to draw is refused here, not after the moves before it)."""
    from ..drawing import find_pen, find_sheet, plan_on_sheet, read_drawing

    with _about("sheet"):
        find_sheet(scene, sheet)
    with _about("pen"):
        find_pen(scene, pen)
    with _about("file"):
        read_drawing(file)
    with _about():
        plan_on_sheet(scene, file, sheet, pen, fit=fit)


def check_play(
    scene: Scene,
    file: Path,
    on: str | None = None,
    tempo: float | None = None,
    transpose: int | None = None,
) -> None:
    """``music.play``: tempo, transpose, the instrument, the score as it reads it and
    every note on a bar or drum (``music.score_on``). Tempi and transpositions are said
    as the script writes them (``tempo 46%``)."""
    from ..music import check_tempo, check_transpose, instruments, load_score, score_on

    with _about("tempo"):
        check_tempo(tempo, script=True)
    with _about("transpose"):
        shift = check_transpose(transpose)
    with _about("on"):
        instruments(scene, on)
    with _about("file"):
        load_score(file, shift)
    with _about():
        score_on(scene, file, on, transpose, script=True)
