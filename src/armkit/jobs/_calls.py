"""The jobs' functions and their checks, by reference: each a small function that
imports the job's package (or the script checker's ``_job_checks``) when it is called,
so ``armkit --help`` and the checker's parse load none of them (``JOBS`` names these as
its specs' ``call`` and ``check``)."""

from __future__ import annotations

from typing import Any


def pick(*args: Any, **kwargs: Any) -> object:
    from ..tasks import pick

    return pick(*args, **kwargs)


def place(*args: Any, **kwargs: Any) -> object:
    from ..tasks import place

    return place(*args, **kwargs)


def move_item(*args: Any, **kwargs: Any) -> object:
    from ..tasks import move_item

    return move_item(*args, **kwargs)


def rotate_cube(*args: Any, **kwargs: Any) -> object:
    from ..tasks import rotate_cube

    return rotate_cube(*args, **kwargs)


def stack(*args: Any, **kwargs: Any) -> object:
    from ..tasks import stack

    return stack(*args, **kwargs)


def search(*args: Any, **kwargs: Any) -> object:
    from ..tasks import search

    return search(*args, **kwargs)


def draw(*args: Any, **kwargs: Any) -> object:
    from ..drawing import draw

    return draw(*args, **kwargs)


def play(*args: Any, **kwargs: Any) -> object:
    from ..music import play

    return play(*args, **kwargs)


def reach(*args: Any, **kwargs: Any) -> object:
    from ..tasks import reach

    return reach(*args, **kwargs)


def check_pick(*args: Any, **kwargs: Any) -> None:
    from ..script.job_checks import check_pick as check

    check(*args, **kwargs)


def check_place(*args: Any, **kwargs: Any) -> None:
    from ..script.job_checks import check_place as check

    check(*args, **kwargs)


def check_move_item(*args: Any, **kwargs: Any) -> None:
    from ..script.job_checks import check_move_item as check

    check(*args, **kwargs)


def check_rotate_cube(*args: Any, **kwargs: Any) -> None:
    from ..script.job_checks import check_rotate_cube as check

    check(*args, **kwargs)


def check_stack(*args: Any, **kwargs: Any) -> None:
    from ..script.job_checks import check_stack as check

    check(*args, **kwargs)


def check_search(*args: Any, **kwargs: Any) -> None:
    from ..script.job_checks import check_search as check

    check(*args, **kwargs)


def check_draw(*args: Any, **kwargs: Any) -> None:
    from ..script.job_checks import check_draw as check

    check(*args, **kwargs)


def check_play(*args: Any, **kwargs: Any) -> None:
    from ..script.job_checks import check_play as check

    check(*args, **kwargs)
