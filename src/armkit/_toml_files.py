"""Data files shipped inside a package (the arm models, the scenes): their names, and a
name or a path resolved to one file."""

from __future__ import annotations

from collections.abc import Callable
from importlib import resources
from pathlib import Path


def shipped(package: str, folder: str) -> list[str]:
    """Names (without ``.toml``) of the TOML files shipped in ``package``/``folder``, sorted."""
    root = resources.files(package) / folder
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
            return Path(str(resources.files(package) / folder / text))
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
    return Path(str(resources.files(package) / folder / f"{text}.toml"))
