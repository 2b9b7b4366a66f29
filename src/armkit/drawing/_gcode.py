"""G-code files to a ``Figure``: what a pen plotter would draw.

Read: G0 G1 (lines), G2 G3 (arcs, centre by I J relative to the start; end
equal to start: a full circle), G4 (dwell P or S, in seconds as RS274NGC and
GRBL read P), G17 (the XY plane, the only one), G20 G21 (inch, mm), G90 G91
(absolute, relative), G28 (lift the pen and go home to X0 Y0, through the given
point if any), M3 M4 (pen down) M5 (pen up), M300 S30 (down) S50 (up), M2 M30
(end), F and S (speeds, not used), N (block numbers). The pen is also down while
Z <= ``z_down`` until the file first uses M3 / M4 / M5 / M300: from then on
those alone move the pen. A move draws only if the pen is down at its start and
its end.
Anything else is refused with its line and column.
"""

from __future__ import annotations

import codecs
import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from .._input_limits import MAX_SEGMENTS, LimitError, check_lines, decode
from ._errors import DrawingError
from ._figure import Figure
from ._gcode_words import Word, words_of
from ._segments import EllipticArc, FigurePath, Line, Segment
from ._svg import read_bytes

LETTERS = "XYZIJFPS"
G_CODES = {0, 1, 2, 3, 4, 17, 20, 21, 28, 90, 91}
M_CODES = {2, 3, 4, 5, 30, 300}
SUPPORTED = "G0 G1 G2 G3 G4 G17 G20 G21 G28 G90 G91 M2 M3 M4 M5 M30 M300 and X Y Z I J F P S N"
UTF16 = (codecs.BOM_UTF16_LE, codecs.BOM_UTF16_BE)
ARC_RADIUS_SLACK = 5e-5  # [m]: start and end radii of an arc may differ by this (or 0.1 %)


@dataclass
class _State:
    """The interpreter's state: position [m], modes, pen and the runs drawn so far."""

    file: str
    z_down: float
    xy: np.ndarray = field(default_factory=lambda: np.zeros(2))
    z: float = math.inf  # unknown: the pen is up until Z or M3 says otherwise
    unit: float = 1e-3  # metres per file unit (G21)
    relative: bool = False
    motion: int | None = None
    down: bool = False
    by_m: bool = False  # once M3 / M5 / M300 is used, they alone move the pen
    runs: list[list[Segment]] = field(default_factory=list)
    dwell: float = 0.0
    segments: int = 0  # drawn so far


def read_gcode(path: str | Path, *, z_down: float = 0.0) -> Figure:
    """Read a G-code file; the pen is down while Z <= ``z_down`` [m] or after M3 / M300 S30.
    Raise ``DrawingError`` naming the file, line and column of the first problem."""
    name = str(path)
    text = _text(read_bytes(path), name)
    st = _State(name, z_down)
    for number, line in enumerate(text.split("\n"), start=1):  # lines as editors count them
        if _run_line(st, words_of(line.rstrip("\r"), number, name), number):
            break
    paths = tuple(FigurePath(tuple(r)) for r in st.runs if r)
    return Figure(paths, np.eye(3), source=name, dwell=st.dwell)


def _text(data: bytes, name: str) -> str:
    """The file's text: UTF-8 (bytes that are not read as U+FFFD, for a comment in
    another encoding) or UTF-16 with its BOM; lines at most ``MAX_LINE_CHARS``."""
    try:
        text = decode(data, name) if data.startswith(UTF16) else data.decode("utf-8", "replace")
        check_lines(text, name)
    except LimitError as exc:
        raise DrawingError(
            exc.problem, file=name, line=exc.line or None, column=exc.column or None
        ) from None
    return text


def _fail(st: _State, line: int, word: Word | None, what: str) -> DrawingError:
    return DrawingError(what, file=st.file, line=line, column=word.column if word else 1)


def _split(st: _State, words: list[Word], line: int) -> tuple[list[Word], dict[str, Word]]:
    """The G and M words of a line, and its parameters by letter; refuse the rest."""
    codes, params = [], {}
    for w in words:
        if w.letter in "GM":
            known = G_CODES if w.letter == "G" else M_CODES
            if w.value != int(w.value) or int(w.value) not in known:
                raise _fail(st, line, w, f"{w.text} is not supported (armkit reads {SUPPORTED})")
            codes.append(w)
        elif w.letter in LETTERS:
            if w.letter in params:
                raise _fail(st, line, w, f"{w.letter} is given twice on the line; keep one")
            params[w.letter] = w
        else:
            hint = "; this looks like a 3D printer file" if w.letter == "E" else ""
            hint = "; give the arc centre with I and J" if w.letter == "R" else hint
            raise _fail(st, line, w, f"{w.text} is not supported (armkit reads {SUPPORTED}){hint}")
    return codes, params


def _run_line(st: _State, words: list[Word], line: int) -> bool:
    """Carry out one line; True at the end of the program (M2, M30)."""
    codes, params = _split(st, words, line)
    motion = [w for w in codes if w.letter == "G" and int(w.value) in (0, 1, 2, 3, 28)]
    if len(motion) > 1:
        raise _fail(st, line, motion[1], f"{motion[0].text} and {motion[1].text} on one line")
    for w in codes:
        if _modal(st, w, params, line):
            return True
    moving = any(k in params for k in "XYZ")
    if motion and int(motion[0].value) == 28:
        _home(st, params)
    elif motion or moving:
        if st.motion is None:
            raise _fail(st, line, words[0], "coordinates before any G0 / G1 / G2 / G3")
        _move(st, st.motion, params, line, motion[0] if motion else words[0])
    for letter in "IJ":
        if letter in params and st.motion not in (2, 3):
            raise _fail(st, line, params[letter], f"{letter} is only for arcs (G2, G3)")
    return False


def _modal(st: _State, w: Word, params: dict[str, Word], line: int) -> bool:
    """Apply one G or M code's mode change; True for M2 / M30."""
    code = int(w.value)
    if w.letter == "G":
        if code in (0, 1, 2, 3):
            st.motion = code
        elif code in (20, 21):
            st.unit = 0.0254 if code == 20 else 1e-3
        elif code in (90, 91):
            st.relative = code == 91
        elif code == 4:
            st.dwell += _dwell(st, params, line, w)
        return False
    if code in (2, 30):
        return True
    st.by_m = True
    if code == 300:
        s = params.get("S")
        if s is None or s.value not in (30.0, 50.0):
            raise _fail(st, line, s or w, "M300 needs S30 (pen down) or S50 (pen up)")
        _pen(st, s.value == 30.0)
    else:
        _pen(st, code in (3, 4))
    return False


def _dwell(st: _State, params: dict[str, Word], line: int, w: Word) -> float:
    p = params.get("P") or params.get("S")
    if p is None or p.value < 0:
        raise _fail(st, line, p or w, "G4 needs a pause P or S >= 0 [s]")
    return p.value


def _pen(st: _State, down: bool) -> None:
    """Lower or lift the pen; a pen lowered and lifted in one place leaves a dot."""
    if down and not st.down:
        st.runs.append([])
    if not down and st.down and not st.runs[-1]:
        st.runs[-1].append(Line(st.xy.copy(), st.xy.copy()))
    st.down = down


def _target(st: _State, params: dict[str, Word]) -> tuple[np.ndarray, float]:
    """Where the move ends: XY [m] and Z [m]."""
    xy, z = st.xy.copy(), st.z
    for i, letter in enumerate("XY"):
        if letter in params:
            v = params[letter].value * st.unit
            xy[i] = xy[i] + v if st.relative else v
    if "Z" in params:
        v = params["Z"].value * st.unit
        z = (0.0 if math.isinf(z) else z) + v if st.relative else v
    return xy, z


def _move(st: _State, mode: int, params: dict[str, Word], line: int, word: Word) -> None:
    xy, z = _target(st, params)
    by_z = "Z" in params and not st.by_m
    down_after = z <= st.z_down if by_z else st.down
    seg: Segment | None = None
    if mode in (2, 3):
        seg = _arc(st, xy, params, line, word, clockwise=mode == 2)
    elif not np.array_equal(xy, st.xy):
        seg = Line(st.xy.copy(), xy.copy())
    if seg is not None and st.down and down_after:
        st.runs[-1].append(seg)
        st.segments += 1
        if st.segments > MAX_SEGMENTS:
            raise _fail(
                st,
                line,
                word,
                f"more than {MAX_SEGMENTS} moves that draw; simplify the drawing or split it",
            )
    st.xy, st.z = xy, z
    _pen(st, down_after)


def _arc(
    st: _State, end: np.ndarray, params: dict[str, Word], line: int, word: Word, clockwise: bool
) -> EllipticArc:
    if "I" not in params and "J" not in params:
        raise _fail(st, line, word, f"{word.text} needs the arc centre: I and/or J")
    offset = np.array([params[k].value if k in params else 0.0 for k in "IJ"]) * st.unit
    center = st.xy + offset
    r0, r1 = float(np.linalg.norm(st.xy - center)), float(np.linalg.norm(end - center))
    if r0 == 0.0:
        raise _fail(st, line, word, "arc of radius 0: I and J are both 0")
    if abs(r1 - r0) > max(ARC_RADIUS_SLACK, 1e-3 * r0):
        raise _fail(
            st,
            line,
            word,
            f"arc end is {r1 * 1e3:.3f} mm from the centre but the start {r0 * 1e3:.3f} mm; "
            "fix I, J or the end point",
        )
    a0 = math.atan2(*(st.xy - center)[::-1])
    a1 = math.atan2(*(end - center)[::-1])
    sweep = (a0 - a1) % (2 * math.pi) if clockwise else (a1 - a0) % (2 * math.pi)
    sweep = sweep or 2 * math.pi  # end == start: a full circle
    return EllipticArc(center, r0, r0, 0.0, a0, -sweep if clockwise else sweep)


def _home(st: _State, params: dict[str, Word]) -> None:
    """G28: lift the pen, go through the given point (if any) to X0 Y0."""
    _pen(st, False)
    st.xy, _ = _target(st, params)
    st.xy, st.z = np.zeros(2), math.inf
