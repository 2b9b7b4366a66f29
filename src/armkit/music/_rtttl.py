"""RTTTL, the Nokia ring-tone language: ``name:d=4,o=5,b=120:8e,8e,e,c.6``.

Three parts split by ``:``: a name, the defaults ``d`` (duration 1, 2, 4, 8, 16,
32: a whole note to a 32nd; default 4), ``o`` (octave 1..8; default 6) and ``b``
(quarter notes per minute 1..1000; default 63), then the notes separated by commas:
``[duration]letter[#][.][octave][.]`` with letter ``a..g`` or ``p`` (a pause) and
``.`` one and a half times as long. Octaves are scientific: ``a4`` is 440 Hz, C4 = MIDI 60.
RTTTL has no loudness: every note gets ``velocity``.
"""

from __future__ import annotations

import re
from typing import NoReturn

from ._score import MAX_SECONDS, Note, Score, ScoreError, make_score

_NOTE = re.compile(r"(\d{0,2})([a-gA-GpP])(#?)(\.?)(\d?)(\.?)")
_STEPS = {"c": 0, "d": 2, "e": 4, "f": 5, "g": 7, "a": 9, "b": 11}
_DURATIONS = (1, 2, 4, 8, 16, 32)


def parse_rtttl(text: str, source: str = "<text>", velocity: int = 96) -> Score:
    """Read one RTTTL tune into a Score; ScoreError names file:line:column and the token."""
    first = text.find(":")
    second = text.find(":", first + 1) if first >= 0 else -1
    if second < 0:
        rest = text[first + 1 :] if first >= 0 else text
        lead = len(rest) - len(rest.lstrip())
        _fail(
            text,
            source,
            (first + 1 if first >= 0 else 0) + lead,
            rest.strip()[:20],
            "an RTTTL tune is name:settings:notes, e.g. tune:d=4,o=5,b=120:c,e,g",
        )
    d, o, bpm = _settings(text, first + 1, second, source)
    notes: list[Note] = []
    time = 0.0
    for start, item in _items(text, second + 1, len(text)):
        note, seconds = _note(text, start, item, (d, o, bpm), source, velocity)
        if note is not None:
            notes.append(Note(time, note[0], velocity, seconds, False, note[1]))
        time += seconds
        if time > MAX_SECONDS:
            _fail(text, source, start, item, f"the tune runs past {MAX_SECONDS:.0f} s")
    return make_score(notes, source)


def _items(text: str, begin: int, end: int) -> list[tuple[int, str]]:
    """(index of the first non-space character, stripped text) of each comma-separated item."""
    out, start = [], begin
    for piece in text[begin:end].split(","):
        lead = len(piece) - len(piece.lstrip())
        out.append((start + lead, piece.strip()))
        start += len(piece) + 1
    if len(out) > 1 and not out[-1][1]:
        out.pop()  # one trailing comma is harmless
    return out


def _settings(text: str, begin: int, end: int, source: str) -> tuple[int, int, float]:
    values = {"d": 4.0, "o": 6.0, "b": 63.0}
    allowed = {
        "d": "a duration 1, 2, 4, 8, 16 or 32",
        "o": "an octave 1..8",
        "b": "a tempo 1..1000",
    }
    if not text[begin:end].strip():
        return 4, 6, 63.0
    for start, item in _items(text, begin, end):
        key, _, value = item.partition("=")
        key = key.strip().lower()
        if key not in values:
            _fail(text, source, start, item, "a setting is d=, o= or b= (duration, octave, tempo)")
        try:
            number = float(value.strip())
        except ValueError:
            number = float("nan")
        ok = {
            "d": number in _DURATIONS,
            "o": number.is_integer() and 1 <= number <= 8,
            "b": 1.0 <= number <= 1000.0,
        }[key]
        if not ok:
            _fail(text, source, start, item, f"{key} must be {allowed[key]}")
        values[key] = number
    return int(values["d"]), int(values["o"]), values["b"]


def _note(
    text: str, start: int, item: str, defaults: tuple[int, int, float], source: str, velocity: int
) -> tuple[tuple[int, str] | None, float]:
    """((MIDI number, where) or None for a pause, length [s]) of one note item."""
    d, o, bpm = defaults
    m = _NOTE.fullmatch(item)
    if not item:
        _fail(text, source, start, ",", "an empty note between commas; remove the extra comma")
    if m is None:
        _fail(
            text, source, start, item, "a note is [duration]letter[#][.][octave], e.g. 8c#.6 or 4p"
        )
    length, letter, sharp, dot1, octave, dot2 = m.groups()
    value = int(length) if length else d
    if value not in _DURATIONS:
        _fail(text, source, start, item, "the duration must be 1, 2, 4, 8, 16 or 32")
    if dot1 and dot2:
        _fail(text, source, start, item, "one dot per note")
    seconds = 4.0 / value * 60.0 / bpm * (1.5 if dot1 or dot2 else 1.0)
    if letter.lower() == "p":
        return None, seconds
    octave_number = int(octave) if octave else o
    pitch = 12 * (octave_number + 1) + _STEPS[letter.lower()] + (1 if sharp else 0)
    if not 1 <= octave_number <= 8 or pitch > 127:
        _fail(text, source, start, item, "the octave must be 1..8")
    line, column = position(text, start)
    return (pitch, f"{source}:{line}:{column}"), seconds


def position(text: str, index: int) -> tuple[int, int]:
    """1-based (line, column) of ``index`` in ``text``."""
    index = max(0, min(index, len(text)))
    line = text.count("\n", 0, index) + 1
    return line, index - (text.rfind("\n", 0, index) + 1) + 1


def _fail(text: str, source: str, index: int, token: str, problem: str) -> NoReturn:
    line, column = position(text, index)
    raise ScoreError(source, line, column, token, problem)
