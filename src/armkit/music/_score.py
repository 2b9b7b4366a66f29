"""One typed score for every input format: notes with onset, pitch, loudness, length.

Times are seconds from the start of the piece (tempo changes already applied);
pitches are MIDI note numbers (60 = C4 = middle C, 69 = A4 = 440 Hz).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from numbers import Integral

from .._errors import ArmkitError, InputError
from .._input_limits import MAX_NOTES, LimitError, where
from .._inputs import is_number, shown
from ..scene import note_name as note_name
from ..scene import note_number

MAX_SECONDS = 3600.0  # the longest piece armkit plays [s]
# The tempo factors armkit plays a piece at (1 = as written), everywhere: ``--tempo``,
# a script's ``tempo P%``, ``play``, ``plan_performance`` and ``Score.at_tempo``. A
# tenth of the written speed is as slow as a piece stays a piece; 4 times is beyond
# what a servo arm strikes in time for any tune written to be played (the shipped ones
# are refused from about 1.2).
MIN_TEMPO, MAX_TEMPO = 0.1, 4.0


class ScoreError(ArmkitError, ValueError):
    """A score file is unreadable or wrong. The message starts with
    ``file:line:column:`` and names the offending token; one about the whole file
    (``ScoreError.whole``: it cannot be read; line 0) starts with ``file:``, one in a
    MIDI file (``ScoreError.at_byte``) with ``file: byte N (track K):``.

    Attributes:
        file: the file (or ``"<text>"``).
        line, column: 1-based position of the token; for a binary MIDI file the
            line is the track (0 = header) and the column the byte offset.
        token: the offending text (or bytes in hex), possibly empty at the end of a file.
    """

    def __init__(self, file: str, line: int, column: int, token: str, problem: str) -> None:
        shown = f"{token!r}" if token else "end of input"
        super().__init__(f"{where(file, line, column)}: {problem} (at {shown})")
        self.file, self.line, self.column, self.token = file, line, column, token

    @classmethod
    def unreadable(cls, file: str, exc: LimitError) -> ScoreError:
        """The file cannot be read, or is beyond a limit of ``_input_limits``."""
        cause = exc.__context__
        if exc.line == 0 and isinstance(cause, OSError):
            return cls.whole(file, f"cannot read the file: {cause.strerror or cause}")
        if exc.line == 0:
            return cls.whole(file, exc.problem)
        err = cls(file, exc.line, exc.column, "", exc.problem)
        err.args = (str(exc),)
        return err

    @classmethod
    def at_byte(cls, file: str, chunk: int, offset: int, token: str, problem: str) -> ScoreError:
        """An error in a binary (MIDI) file: ``file: byte OFFSET (track N): problem``
        (``line`` is the chunk, 0 = the header; ``column`` the byte offset)."""
        err = cls(file, chunk, offset, token, problem)
        part = f"track {chunk}" if chunk else "the header"
        err.args = (f"{file}: byte {offset} ({part}): {problem} (at {token!r})",)
        return err

    @classmethod
    def whole(cls, file: str, problem: str) -> ScoreError:
        """An error about the whole file (line and column 0, no token): ``file: problem``."""
        err = cls(file, 0, 0, "", problem)
        err.args = (f"{file}: {problem}",)
        return err

    @classmethod
    def of_note(cls, file: str, note: Note, problem: str) -> ScoreError:
        """An error about ``note``, at the place it was written (``note.where``:
        ``file:line:column``, or a MIDI file's ``file: message N``; the file if not known)."""
        head, line, column = note.where or file, 0, 0
        place = note.where.rsplit(":", 2)
        if len(place) == 3 and place[1].isdigit() and place[2].isdigit():
            head, line, column = place[0], int(place[1]), int(place[2])
            return cls(head, line, column, note.name, problem)
        err = cls(file, 0, 0, note.name, problem)
        err.args = (f"{head}: {problem} (at {note.name!r})",)
        return err


@dataclass(frozen=True)
class Note:
    """One note of a score.

    Attributes:
        onset: start time [s] from the start of the piece, >= 0.
        pitch: MIDI note number 0..127 (for drums, the General MIDI drum: 36 kick, 38 snare).
        velocity: MIDI loudness 1..127.
        duration: length [s], >= 0 (a mallet strike sounds however long it is written).
        drum: True for a drum hit (MIDI channel 10, or a drum name in a note list).
        where: where it was written (``"tune.txt:3:7"``), for messages.
    """

    onset: float
    pitch: int
    velocity: int
    duration: float
    drum: bool = False
    where: str = ""

    @property
    def name(self) -> str:
        """``"C#4"`` for a pitched note, ``"drum 38"`` for a drum hit."""
        return f"drum {self.pitch}" if self.drum else note_name(self.pitch)


@dataclass(frozen=True)
class Score:
    """A piece: notes sorted by onset (ties by pitch).

    Attributes:
        notes: the notes.
        source: the file it was read from (or ``"<text>"``).
    """

    notes: tuple[Note, ...]
    source: str = "<text>"

    @property
    def duration(self) -> float:
        """Time [s] until the last note ends."""
        return max((n.onset + n.duration for n in self.notes), default=0.0)

    def transposed(self, semitones: int) -> Score:
        """Every pitched note moved by ``semitones`` (drums stay). InputError unless it
        is a whole number; ScoreError at the first note it moves out of the MIDI range
        0..127, naming where the note is written and the shifts that keep every note in."""
        if isinstance(semitones, bool) or not isinstance(semitones, Integral):
            raise InputError(
                f"semitones must be a whole number (12 = an octave up), got {shown(semitones)}"
            )
        shift = int(semitones)
        pitched = [n for n in self.notes if not n.drum]
        for n in pitched:
            if not 0 <= n.pitch + shift <= 127:
                low = -min(m.pitch for m in pitched)
                high = 127 - max(m.pitch for m in pitched)
                raise ScoreError.of_note(
                    self.source,
                    n,
                    f"transposing by {shift} moves {n.name} (MIDI {n.pitch}) to MIDI "
                    f"{n.pitch + shift}, outside the MIDI range 0..127; {low}..{high} keeps every note in",
                )
        moved = tuple(n if n.drum else replace(n, pitch=n.pitch + shift) for n in self.notes)
        return Score(moved, self.source)

    def at_tempo(self, factor: float) -> Score:
        """The piece played ``factor`` times as fast (2.0 = twice the tempo): every
        onset and length divided by ``factor``. InputError unless it is a number in
        ``MIN_TEMPO..MAX_TEMPO`` (``tempo_factor``)."""
        factor = tempo_factor(factor)
        return Score(
            tuple(
                replace(n, onset=n.onset / factor, duration=n.duration / factor) for n in self.notes
            ),
            self.source,
        )


def tempo_factor(value: object, *, percent: bool = False) -> float:
    """``value`` as a tempo factor, ``MIN_TEMPO..MAX_TEMPO`` (1 = as written); else
    InputError, the one message for every way a tempo is given, the value shown as it
    was written: a factor, or with ``percent`` in % (a script's ``tempo 45%``)."""
    if is_number(value) and math.isfinite(float(value)):  # type: ignore[arg-type]
        factor = float(value)  # type: ignore[arg-type]
        if MIN_TEMPO <= factor <= MAX_TEMPO:
            return factor
        got = f"{factor * 100:.6g}%" if percent else f"{factor:.6g}"
    else:
        got = shown(value)
    raise InputError(f"tempo must be {tempo_range()} of the written speed, got {got}")


def tempo_range() -> str:
    """The tempo range as every message and help text says it: ``a factor 0.1..4
    (10%..400%)``."""
    return f"a factor {MIN_TEMPO:g}..{MAX_TEMPO:g} ({MIN_TEMPO * 100:g}%..{MAX_TEMPO * 100:g}%)"


def make_score(notes: list[Note], source: str) -> Score:
    """Sort ``notes`` into a Score; ScoreError if there are none."""
    if not notes:
        raise ScoreError(source, 1, 1, "", "the score has no notes; write at least one")
    if len(notes) > MAX_NOTES:
        raise ScoreError.of_note(
            source, notes[MAX_NOTES], f"more than {MAX_NOTES} notes; split the piece"
        )
    return Score(tuple(sorted(notes, key=lambda n: (n.onset, n.pitch))), source)


def parse_pitch(text: str) -> int | None:
    """``"C4"``, ``"c#4"``, ``"Bb3"``, ``"A-1"`` -> MIDI number; None if it is not
    a note name or is outside 0..127 (the scene's ``note_number``, one reading of names)."""
    if not isinstance(text, str):
        return note_number(text)  # refused there: not a string
    return note_number(text) if text == text.strip() else None
