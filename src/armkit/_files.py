"""Where armkit keeps what it must remember about a unit, and how it writes it.

One config directory for every layer (OWI state, servo pulse tables, the
simulator's pose) and one atomic writer, so a crash or a kill never leaves a
file half written.
"""

from __future__ import annotations

import os
import tempfile
from pathlib import Path


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
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".tmp")
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
