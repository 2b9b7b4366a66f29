"""Where armkit keeps what it must remember about a unit, and how it writes it.

One config directory for every layer (OWI state, servo pulse tables, the
simulator's pose), one atomic writer, so a crash or a kill never leaves a
file half written, and the one check of every file armkit is asked to write
(``check_output_path``), made before anything moves.
"""

from __future__ import annotations

import errno
import os
import stat
from collections.abc import Callable, Sequence
from pathlib import Path

from ._errors import InputError

ANYWHERE = "choose a file in a folder you can write to"


def config_dir() -> Path:
    """``$ARMKIT_CONFIG_DIR``, else ``$XDG_CONFIG_HOME/armkit``, else ``~/.config/armkit`` (not created)."""
    if os.environ.get("ARMKIT_CONFIG_DIR"):
        return Path(os.environ["ARMKIT_CONFIG_DIR"]).expanduser()
    xdg = os.environ.get("XDG_CONFIG_HOME")
    return (Path(xdg) if xdg else Path.home() / ".config") / "armkit"


def write_atomic(path: Path, text: str, durable: bool = True) -> None:
    """Write ``text`` to ``path`` so readers see the old file or the new one, never half
    of one: a temporary file in the same directory, fsync, ``os.replace``, fsync of the
    directory. ``durable=False`` skips the fsyncs (still atomic, not power-loss safe):
    for simulations."""
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = _temporary(path)
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as handle:
            os.fchmod(handle.fileno(), 0o644)  # a config file, not a secret
            handle.write(text)
            handle.flush()
            if durable:
                os.fsync(handle.fileno())
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise
    if durable:
        _fsync_dir(path.parent)


def _temporary(path: Path) -> tuple[int, str]:
    """A new temporary file beside ``path`` (the atomic writer's): (open fd, its name)."""
    import tempfile  # here: it loads shutil, random, bz2, lzma (10 ms of every command)

    return tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".tmp")


def check_output_path(
    path: str | os.PathLike[str], option: str = "", suffixes: Sequence[str] = ()
) -> Path:
    """``path`` (``~`` expanded) once it is proven that a file can be written there;
    writes nothing that stays. Call it before anything moves or any long work starts.

    Checked in order: a name is given; it is not a directory; it ends in one of
    ``suffixes`` (any suffix if empty; compared lower-case, e.g. ``(".png", ".svg")``);
    it is not another non-regular file (a device, a pipe); its folder exists and is a folder; an
    existing file is writable; and a temporary file created and removed beside it
    (what ``write_atomic`` does) succeeds, so a folder such as /proc, a read-only mount
    or a permission problem is refused here and not after the job.

    Raises:
        InputError: one line, ``[option: ]cannot write PATH: why; what to do``.
    """
    given = os.fspath(path)
    p = Path(given).expanduser()
    folder = p.parent

    def refuse(why: str, todo: str = ANYWHERE) -> InputError:
        head = f"{option}: " if option else ""
        return InputError(f"{head}cannot write {given or repr(given)}: {why}; {todo}")

    if not given.strip():
        raise refuse("no file name given", "give a file name")
    try:
        mode = p.stat().st_mode if p.exists() else None
    except OSError as exc:
        raise refuse(f"cannot look at it ({exc.strerror})") from None
    if mode is not None and stat.S_ISDIR(mode):
        raise refuse("it is a directory", "give a file name inside it")
    wanted = tuple(s.lower() for s in suffixes)
    if wanted and p.suffix.lower() not in wanted:
        ends = wanted[0] if len(wanted) == 1 else "one of " + ", ".join(wanted)
        raise refuse(f"the file name must end in {ends}", f"name it like out{wanted[0]}")
    if mode is not None and not stat.S_ISREG(mode):
        raise refuse("it is not a regular file (a device or a pipe)")
    if not folder.exists():
        raise refuse(
            f"the folder {folder} does not exist", "create it first or choose another folder"
        )
    if not folder.is_dir():
        raise refuse(f"{folder} is not a folder")
    if mode is not None and not os.access(p, os.W_OK):
        raise refuse("the file is read-only")
    _probe(p, refuse)
    return p


def _probe(path: Path, refuse: Callable[..., InputError]) -> None:
    """Create and remove the atomic writer's temporary file beside ``path``."""
    try:
        fd, tmp = _temporary(path)
    except OSError as exc:
        if exc.errno == errno.ENAMETOOLONG:
            raise refuse("the file name is too long", "choose a shorter name") from None
        raise refuse(f"the folder {path.parent} does not take new files ({_why(exc)})") from None
    os.close(fd)
    Path(tmp).unlink(missing_ok=True)


def folder_problem(folder: Path) -> str | None:
    """Why files cannot be made in ``folder`` (or, while it does not exist, in the
    nearest folder above it, where it would be created), proven by creating and
    removing a temporary file there; None if they can."""
    probe = folder
    try:
        while not probe.exists() and probe.parent != probe:
            probe = probe.parent
    except OSError as exc:
        return f"{probe} cannot be looked at ({_why(exc)})"
    if not probe.is_dir():
        return f"{probe} is not a folder"
    import tempfile  # here, as in ``_temporary``

    try:
        fd, tmp = tempfile.mkstemp(dir=probe, prefix=".armkit-probe.", suffix=".tmp")
    except OSError as exc:
        return f"the folder {probe} does not take new files ({_why(exc)})"
    os.close(fd)
    Path(tmp).unlink(missing_ok=True)
    return None


def _why(exc: OSError) -> str:
    return exc.strerror or type(exc).__name__


def _fsync_dir(directory: Path) -> None:
    """Make the rename itself durable (best effort: not every platform allows it)."""
    try:
        fd = os.open(directory, os.O_RDONLY)
    except OSError:
        return
    try:
        os.fsync(fd)
    except OSError:
        pass
    finally:
        os.close(fd)
