"""TOML data files (the arm models, the scenes): the names of those shipped inside a
package, a name or a path resolved to one file, and a file read within armkit's
input limits."""

from __future__ import annotations

import re
import sys
import tomllib
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING, Any

from ._input_limits import MAX_TOML_BYTES, LimitError, position, read_text, where
from ._toml_shape import check_toml_shape

if TYPE_CHECKING:
    from importlib.resources.abc import Traversable


def _folder(package: str, folder: str) -> Path | Traversable:
    """``package``/``folder``: beside the package's ``__init__`` when it is a directory
    there (an installed or checked-out armkit: no importlib.resources and its zipfile to
    load, milliseconds of every command's start), else through importlib.resources."""
    init = getattr(sys.modules.get(package), "__file__", None)  # the caller's own package
    if init is not None and (Path(init).parent / folder).is_dir():
        return Path(init).parent / folder
    from importlib import resources

    return resources.files(package) / folder


def shipped(package: str, folder: str) -> list[str]:
    """Names (without ``.toml``) of the TOML files shipped in ``package``/``folder``, sorted."""
    root = _folder(package, folder)
    return sorted(p.name[:-5] for p in root.iterdir() if p.name.endswith(".toml"))


def resolve(
    name_or_path: str | Path,
    package: str,
    folder: str,
    error: Callable[[str], Exception],
    *,
    kind: str,
    noun: str,
    files: str = ".toml",
) -> Path:
    """The file ``name_or_path`` names: a path (ends in ``.toml`` or has a ``/``) that must
    exist, or the name of a file shipped in ``package``/``folder``; a bare shipped file
    name (``xylophone.toml``) not found here is the shipped file.

    Raises:
        ``error(message)``: no such file ("no such {kind} file"), a directory ("is a
            directory; give a {files} file"), or an unknown name ("unknown {noun} ...;
            shipped {noun}s are ...").
    """
    text = str(name_or_path)
    if text.endswith(".toml") or "/" in text or "\\" in text:
        path = Path(text).expanduser()
        if path.is_file():
            return path
        if path.name == text and path.stem in shipped(package, folder):
            return Path(str(_folder(package, folder) / text))
        if path.is_dir():
            raise error(f"{path}: is a directory; give a {files} file")
        raise error(f"{path}: no such {kind} file")
    names = shipped(package, folder)
    if text not in names and Path(text).is_dir():
        raise error(f"{text}: is a directory; give a {files} file or a shipped {noun}'s name")
    if text not in names:
        raise error(
            f"unknown {noun} {text!r}; shipped {noun}s are {', '.join(names)} "
            "(or give a path to a .toml file)"
        )
    return Path(str(_folder(package, folder) / f"{text}.toml"))


def read_toml(
    path: Path, error: Callable[[str], Exception], what: str
) -> tuple[dict[str, Any], str]:
    """The parsed TOML of ``path`` and its text, read within the limits of
    ``_input_limits`` (size, UTF-8, line length) and ``_toml_shape`` (nesting, numbers);
    ``what`` names the kind of file in messages ("scene file").

    Raises:
        ``error(message)``: the message starts with ``FILE:LINE:COL:`` (``FILE:`` when
            it is about the whole file) and says which limit or what TOML wanted.
    """
    name = str(path)
    try:
        text = read_text(path, MAX_TOML_BYTES, what)
        check_toml_shape(text, name)
    except LimitError as exc:
        raise error(str(exc)) from None
    try:
        return tomllib.loads(text), text
    except tomllib.TOMLDecodeError as exc:
        message = str(exc)
        at = _AT.search(message)
        line, column = (int(at[1]), int(at[2])) if at else (0, 0)
        if at is None and message.endswith("(at end of document)"):
            line, column = position(text, len(text))
        message = _AT_ANY.sub("", message).strip()
        raise error(f"{where(name, line, column)}: not valid TOML: {message}") from None
    except (RecursionError, ValueError) as exc:  # beyond what the shape check foresaw
        raise error(f"{name}: not a TOML file armkit can read ({type(exc).__name__})") from None


_AT = re.compile(r"\(at line (\d+), column (\d+)\)")
_AT_ANY = re.compile(r"\(at (?:line \d+, column \d+|end of document)\)")
