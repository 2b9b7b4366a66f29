"""One process per arm: an exclusive, advisory lock on what armkit must not share.

A state file (the OWI's estimate, a simulated arm's true pose) or a serial port
is taken with ``exclusive(path, what)`` for as long as a driver holds it. A
second armkit process asking for the same thing is refused at once with a
message naming the process that holds it; nothing waits, nothing is changed.

The lock is ``flock`` on a small ``<name>.lock`` file beside a state file (or
in the config directory for a device path), so the kernel releases it when the
holder dies, however it dies: a crash or a kill never leaves a stale lock.
"""

from __future__ import annotations

import contextlib
import fcntl
import os
from collections.abc import Iterator
from pathlib import Path

from ._errors import DeviceError
from ._files import config_dir


class Lock:
    """A held lock; ``release()`` (or leaving the ``with``) gives it back. Idempotent."""

    def __init__(self, path: Path, fd: int) -> None:
        self.path = path
        self._fd: int | None = fd

    @property
    def held(self) -> bool:
        """True until released."""
        return self._fd is not None

    def release(self) -> None:
        """Unlock and close (the lock file stays: removing it would race a new holder)."""
        if self._fd is None:
            return
        fd, self._fd = self._fd, None
        with contextlib.suppress(OSError):
            fcntl.flock(fd, fcntl.LOCK_UN)
        os.close(fd)

    def __enter__(self) -> Lock:
        return self

    def __exit__(self, *exc: object) -> None:
        self.release()


def lock_path_for(resource: str | Path) -> Path:
    """The lock file of ``resource``: ``<file>.lock`` beside a state file, or
    ``<config dir>/locks/<device path with / as _>.lock`` for a device (``/dev/ttyUSB0``)."""
    text = str(resource)
    if text.startswith("/dev/"):
        return config_dir() / "locks" / (text.strip("/").replace("/", "_") + ".lock")
    path = Path(text)
    return path.with_name(path.name + ".lock")


def exclusive(resource: str | Path, what: str) -> Lock:
    """Take the lock of ``resource`` (a state file or a device path) or refuse.

    Args:
        resource: the file or device to protect.
        what: how to name it to a person (``"the simulated openmanipulator_x"``).

    Raises:
        DeviceError: another process holds it (the message names its pid), or the
            lock file cannot be created (the message names the directory).
    """
    path = lock_path_for(resource)
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        fd = os.open(path, os.O_RDWR | os.O_CREAT, 0o644)
    except OSError as exc:
        raise DeviceError(
            f"cannot create the lock for {what} in {path.parent}: {exc.strerror}; "
            "set ARMKIT_CONFIG_DIR to a writable directory"
        ) from None
    try:
        fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except OSError:
        holder = _holder(fd)
        os.close(fd)
        who = f"process {holder}" if holder else "another process"
        raise DeviceError(
            f"{what} is in use by {who}; wait for it to finish or stop it, then try again"
        ) from None
    os.ftruncate(fd, 0)
    os.write(fd, str(os.getpid()).encode())
    return Lock(path, fd)


@contextlib.contextmanager
def held(resource: str | Path, what: str) -> Iterator[Lock]:
    """``with held(path, what):`` — ``exclusive`` as a context manager."""
    lock = exclusive(resource, what)
    try:
        yield lock
    finally:
        lock.release()


def _holder(fd: int) -> str:
    with contextlib.suppress(OSError, ValueError):
        return os.pread(fd, 32, 0).decode().strip()
    return ""
