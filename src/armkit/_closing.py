"""Closing a device after a block: the block's own error is the one the user sees."""

from __future__ import annotations

from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import Protocol, TypeVar


class Closeable(Protocol):
    def close(self) -> None: ...


C = TypeVar("C", bound=Closeable)


def close_after(close: Callable[[], object], error: BaseException | None) -> None:
    """Run ``close()``. When the block before it already failed with ``error``, that error
    stays the one raised: a failure of ``close`` (often from the same cause, e.g. a port
    that vanished) is added to it as a note instead of replacing it."""
    if error is None:
        close()
        return
    try:
        close()
    except Exception as cleanup:
        error.add_note(f"and stopping the arm afterwards failed too: {cleanup}")


@contextmanager
def closing(thing: C) -> Iterator[C]:
    """``with closing(driver):`` closes (stops) ``driver`` however the block ends,
    keeping the block's error as the one raised (``close_after``)."""
    try:
        yield thing
    except BaseException as error:
        close_after(thing.close, error)
        raise
    thing.close()
