"""One entry point for every score format, chosen by the file's suffix."""

from __future__ import annotations

from numbers import Integral
from pathlib import Path

from .._input_limits import MAX_SCORE_BYTES, LimitError, check_lines, decode, read_limited
from ._midi import read_midi
from ._notelist import parse_notelist
from ._rtttl import parse_rtttl
from ._score import Score, ScoreError

MIDI_SUFFIXES = (".mid", ".midi")
RTTTL_SUFFIXES = (".rtttl", ".rtx")
NOTELIST_SUFFIXES = (".txt", ".notes")


def load_score(path: str | Path, transpose: int = 0) -> Score:
    """Read a score: MIDI (``.mid``, ``.midi``), RTTTL (``.rtttl``, ``.rtx``) or a note
    list (``.txt``, ``.notes``), then move pitched notes by ``transpose`` semitones.

    Raises:
        ScoreError: unknown suffix, unreadable file, or a mistake in it (file:line:column, token).
    """
    if not isinstance(path, str | Path):
        raise ScoreError.whole(str(path), "a score is a file path (str or Path)")
    if not isinstance(transpose, Integral) or isinstance(transpose, bool):
        raise ScoreError.whole(str(path), f"transpose is whole semitones, got {transpose!r}")
    source, suffix = str(path), Path(path).suffix.lower()
    if suffix in MIDI_SUFFIXES:
        score = read_midi(path)
    elif suffix in RTTTL_SUFFIXES + NOTELIST_SUFFIXES:
        text = read_text(path)
        score = (
            parse_rtttl(text, source) if suffix in RTTTL_SUFFIXES else parse_notelist(text, source)
        )
    else:
        known = ", ".join(MIDI_SUFFIXES + RTTTL_SUFFIXES + NOTELIST_SUFFIXES)
        raise ScoreError(
            source, 0, 0, suffix, f"unknown score format; name the file with one of {known}"
        )
    return score.transposed(int(transpose)) if transpose else score


def read_text(path: str | Path) -> str:
    """The text of ``path`` (UTF-8, or UTF-16 with its BOM) within armkit's input limits
    (``MAX_SCORE_BYTES``, ``MAX_LINE_CHARS``); ScoreError says where it is not."""
    source = str(path)
    try:
        text = decode(read_limited(path, MAX_SCORE_BYTES, "score"), source)
        check_lines(text, source)
    except LimitError as exc:
        raise ScoreError.unreadable(source, exc) from None
    return text
