"""SVG is read safely (issue 33 item 2): a billion-laughs file, an external entity (a
file, a URL), a parameter entity and an external DTD are refused in one
``FILE:LINE:COL:`` line, and nothing but the SVG file itself is opened, read or
connected to while armkit reads it (Python's audit events ``open`` and
``socket.connect``, recorded around the read)."""

from __future__ import annotations

import sys
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

import pytest

from armkit.cli import main
from armkit.drawing import DrawingError, read_svg

SVG = b'<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100">%s</svg>\n'
_RECORDING: list[list[tuple[str, str]]] = []  # the events of the read in progress


def _hook(event: str, args: tuple[object, ...]) -> None:
    if _RECORDING and event in ("open", "socket.connect"):
        _RECORDING[-1].append((event, str(args[0] if event == "open" else args[1])))


_HOOKED: list[bool] = []


@contextmanager
def _recorded(tmp_path: Path) -> Iterator[list[tuple[str, str]]]:
    """The files opened and the sockets connected inside the block (after a first
    drawing is read, so that the modules a read imports are not counted)."""
    warm = tmp_path / "warm.svg"
    warm.write_bytes(SVG % b'<path d="M 0 0 L 50 50"/>')
    read_svg(warm)
    if not _HOOKED:  # an audit hook cannot be removed: one for the whole run, idle outside
        sys.addaudithook(_hook)
        _HOOKED.append(True)
    events: list[tuple[str, str]] = []
    _RECORDING.append(events)
    try:
        yield events
    finally:
        _RECORDING.pop()


def _laughs(levels: int = 10) -> bytes:
    ents = b'<!ENTITY lol0 "lol">\n' + b"".join(
        b'<!ENTITY lol%d "%s">\n' % (k, b"&lol%d;" % (k - 1) * 10) for k in range(1, levels)
    )
    doctype = b"<?xml version='1.0'?>\n<!DOCTYPE svg [\n" + ents + b"]>\n"
    return doctype + SVG % b"<text>&lol%d;</text>" % (levels - 1)


def _secret(tmp_path: Path) -> Path:
    secret = tmp_path / "secret.txt"
    secret.write_text("M 0 0 L 50 50\n")
    return secret


CASES = {
    "a billion laughs": (lambda tmp: _laughs(), "4:15", "billion-laughs"),
    "an external entity (a file)": (
        lambda tmp: (
            b'<?xml version="1.0"?>\n<!DOCTYPE svg [<!ENTITY x SYSTEM "%s">]>\n'
            % _secret(tmp).as_uri().encode()
            + SVG % b"<text>&x;</text>"
        ),
        "2:",
        "an external entity &x;",
    ),
    "an external entity (a URL)": (
        lambda tmp: (
            b'<!DOCTYPE svg [<!ENTITY x SYSTEM "http://127.0.0.1:9/x">]>'
            + SVG % b"<text>&x;</text>"
        ),
        "1:",
        "an external entity &x; (http://127.0.0.1:9/x)",
    ),
    "a parameter entity": (
        lambda tmp: (
            b'<!DOCTYPE svg [<!ENTITY %% p SYSTEM "%s"> %%p;]>' % _secret(tmp).as_uri().encode()
            + SVG % b""
        ),
        "1:",
        "a parameter entity &p;",
    ),
    "an undefined entity": (lambda tmp: SVG % b"<text>&nope;</text>", "1:", "undefined entity"),
}


@pytest.mark.parametrize("name", list(CASES))
def test_refused_in_one_line_at_its_place_reading_nothing_else(
    name: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    make, at, says = CASES[name]
    path = tmp_path / "nasty.svg"
    path.write_bytes(make(tmp_path))
    with _recorded(tmp_path) as events, pytest.raises(DrawingError) as refused:
        read_svg(path)
    assert str(refused.value).startswith(f"{path}:{at}"), refused.value
    assert says in str(refused.value)
    others = [(e, what) for e, what in events if e != "open" or Path(what) != path]
    assert others == [], f"read or connected to more than the file: {others}"

    code = main(["--scene", "drawing", "draw", "svg", str(path), "--dry-run"])
    err = capsys.readouterr().err.strip().splitlines()
    assert code == 2
    assert len(err) == 1 and err[0].startswith(f"armkit: error: {path}:{at}"), err


def test_an_external_dtd_is_not_fetched(tmp_path: Path) -> None:
    dtd = tmp_path / "svg.dtd"
    dtd.write_text('<!ENTITY x "M 0 0 L 9 9">\n')
    path = tmp_path / "dtd.svg"
    path.write_bytes(
        b'<!DOCTYPE svg SYSTEM "%s">' % dtd.as_uri().encode() + SVG % b'<path d="M 0 0 L 50 50"/>'
    )
    with _recorded(tmp_path) as events:
        figure = read_svg(path)
    assert figure.flatten(1e-4)  # the drawing itself is read
    assert [what for e, what in events if e == "open" and Path(what) != path] == []


def test_entities_within_the_limits_are_read(tmp_path: Path) -> None:
    """What a drawing program writes (Illustrator declares its namespaces as entities)."""
    path = tmp_path / "ok.svg"
    path.write_bytes(b'<!DOCTYPE svg [<!ENTITY d "M 0 0 L 50 50">]>' + SVG % b'<path d="&d;"/>')
    (stroke,) = read_svg(path).flatten(1e-4)
    assert len(stroke) == 2
