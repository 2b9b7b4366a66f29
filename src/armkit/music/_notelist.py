"""The plain note list: ``tempo 120`` / ``C4 q  E4 e  G4 e  R q``.

Grammar (whitespace-separated tokens; ``#`` at the start of a token comments out
the rest of the line):

- ``tempo BPM``: quarter notes per minute (1..1000) from here on; may change mid-piece.
- ``velocity N`` (1..127) or a dynamic mark ``ppp pp p mp mf f ff fff``: loudness from here on.
- an event, two tokens on one line: what, then how long.
  What: a note name ``C4``, ``F#3``, ``Bb5`` (C4 = MIDI 60), ``R`` (a rest), a
  drum name (``kick snare hihat openhat crash ride tom1 tom2 tom3 clap``) or
  ``dNN`` (General MIDI drum NN). How long: ``w h q e s t`` (whole .. 32nd),
  each ``.`` adds half again (``q.`` = 1.5 beats), a trailing ``3`` makes a
  triplet (``e3`` = 1/3 beat).
"""

from __future__ import annotations

import re
from collections.abc import Iterator
from dataclasses import dataclass

from ._score import MAX_SECONDS, Note, Score, ScoreError, make_score, parse_pitch

DYNAMICS = {"ppp": 16, "pp": 33, "p": 49, "mp": 64, "mf": 80, "f": 96, "ff": 112, "fff": 127}
DRUMS = {
    "kick": 36,
    "snare": 38,
    "clap": 39,
    "hihat": 42,
    "tom1": 50,
    "tom2": 47,
    "tom3": 45,
    "openhat": 46,
    "crash": 49,
    "ride": 51,
}
_BEATS = {"w": 4.0, "h": 2.0, "q": 1.0, "e": 0.5, "s": 0.25, "t": 0.125}
_DURATION = re.compile(r"([whqest])(\.{0,2})(3?)")
_DRUM_NUMBER = re.compile(r"d(\d{1,3})")


@dataclass(frozen=True)
class Token:
    """One word of the text: its 1-based line and column, and the text."""

    line: int
    column: int
    text: str


@dataclass
class _State:
    """Where the reader is in the piece."""

    time: float = 0.0
    bpm: float = 120.0
    velocity: int = 80


def tokens(text: str) -> Iterator[Token]:
    """The words of ``text`` with their positions, comments dropped."""
    for number, line in enumerate(text.splitlines(), start=1):
        for m in re.finditer(r"\S+", line):
            if m.group().startswith("#"):
                break
            yield Token(number, m.start() + 1, m.group())


def parse_notelist(text: str, source: str = "<text>") -> Score:
    """Read a note list (module doc) into a Score; ScoreError names file:line:column and token."""
    state, notes = _State(), []
    words = list(tokens(text))
    i = 0
    while i < len(words):
        word = words[i]
        following = words[i + 1] if i + 1 < len(words) else None
        if word.text in DYNAMICS:
            state.velocity = DYNAMICS[word.text]
            i += 1
            continue
        if word.text in ("tempo", "velocity"):
            _setting(word, _value_of(word, following, source), state, source)
        else:
            note = _event(word, _duration_of(word, following, source), state, source)
            if note is not None:
                notes.append(note)
        i += 2
    return make_score(notes, source)


def _value_of(word: Token, following: Token | None, source: str) -> Token:
    if following is None or following.line != word.line:
        at = following if following is not None else word
        raise ScoreError(
            source,
            at.line,
            at.column,
            word.text,
            f"{word.text} needs a number after it on the same line",
        )
    return following


def _duration_of(word: Token, following: Token | None, source: str) -> Token:
    if parse_what(word.text) is None:
        raise ScoreError(
            source,
            word.line,
            word.column,
            word.text,
            "unknown word; expected a note (C4, F#3, Bb5), R, a drum name, tempo, velocity or a dynamic (p, mf, f)",
        )
    if following is None or following.line != word.line:
        raise ScoreError(
            source,
            word.line,
            word.column,
            word.text,
            "a note needs a duration after it on the same line (w h q e s t)",
        )
    return following


def _setting(word: Token, value: Token, state: _State, source: str) -> None:
    try:
        number = float(value.text)
    except ValueError:
        number = float("nan")
    if word.text == "tempo":
        if not 1.0 <= number <= 1000.0:
            raise ScoreError(
                source,
                value.line,
                value.column,
                value.text,
                "tempo must be 1..1000 quarter notes per minute",
            )
        state.bpm = number
    else:
        if not (number.is_integer() and 1 <= number <= 127):
            raise ScoreError(
                source,
                value.line,
                value.column,
                value.text,
                "velocity must be a whole number 1..127",
            )
        state.velocity = int(number)


def _event(word: Token, length: Token, state: _State, source: str) -> Note | None:
    """The note of ``word`` lasting ``length`` (None for a rest); advances the time."""
    beats = parse_beats(length.text)
    if beats is None:
        raise ScoreError(
            source,
            length.line,
            length.column,
            length.text,
            "unknown duration; use w h q e s t, '.' for dotted, '3' for a triplet (q. e3)",
        )
    seconds = beats * 60.0 / state.bpm
    what = parse_what(word.text)
    onset, state.time = state.time, state.time + seconds
    if state.time > MAX_SECONDS:
        raise ScoreError(
            source,
            length.line,
            length.column,
            length.text,
            f"the piece runs past {MAX_SECONDS:.0f} s",
        )
    if what is None or what[0] < 0:
        return None
    pitch, drum = what
    return Note(onset, pitch, state.velocity, seconds, drum, f"{source}:{word.line}:{word.column}")


def parse_what(text: str) -> tuple[int, bool] | None:
    """(MIDI number, is a drum) for a note name or drum; (-1, False) for a rest; None if unknown."""
    if text in ("R", "r"):
        return -1, False
    if text in DRUMS:
        return DRUMS[text], True
    m = _DRUM_NUMBER.fullmatch(text)
    if m is not None:
        number = int(m.group(1))
        return (number, True) if number <= 127 else None
    pitch = parse_pitch(text)
    return None if pitch is None else (pitch, False)


def parse_beats(text: str) -> float | None:
    """Length in quarter-note beats of ``q``, ``e.``, ``s3`` ...; None if malformed."""
    m = _DURATION.fullmatch(text)
    if m is None:
        return None
    base, dots, triplet = m.groups()
    beats = _BEATS[base] * (1.0 + sum(0.5 ** (k + 1) for k in range(len(dots))))
    return beats * 2.0 / 3.0 if triplet else beats
