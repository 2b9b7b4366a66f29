"""One typed score for every input format: notes with onset, pitch, loudness, length.

Times are seconds from the start of the piece (tempo changes already applied);
pitches are MIDI note numbers (60 = C4 = middle C, 69 = A4 = 440 Hz).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

from .._errors import ArmkitError, InputError
from ..scene import note_name as note_name
from ..scene import note_number

MAX_SECONDS = 3600.0  # the longest piece armkit plays [s]


class ScoreError(ArmkitError, ValueError):
    """A score file is unreadable or wrong. The message starts with
    ``file:line:column:`` and names the offending token; one about the whole file
    (``ScoreError.whole``: it cannot be read) starts with ``file:``.

    Attributes:
        file: the file (or ``"<text>"``).
        line, column: 1-based position of the token; for a binary MIDI file the
            line is the track (0 = header) and the column the byte offset.
        token: the offending text (or bytes in hex), possibly empty at the end of a file.
    """

    def __init__(self, file: str, line: int, column: int, token: str, problem: str) -> None:
        shown = f"{token!r}" if token else "end of input"
        super().__init__(f"{file}:{line}:{column}: {problem} (at {shown})")
        self.file, self.line, self.column, self.token = file, line, column, token

    @classmethod
    def whole(cls, file: str, problem: str) -> ScoreError:
        """An error about the whole file (line and column 0, no token): ``file: problem``."""
        err = cls(file, 0, 0, "", problem)
        err.args = (f"{file}: {problem}",)
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
        """Every pitched note moved by ``semitones`` (drums stay); ScoreError if a note
        leaves the MIDI range 0..127."""
        moved = []
        for n in self.notes:
            pitch = n.pitch if n.drum else n.pitch + semitones
            if not 0 <= pitch <= 127:
                raise ScoreError(
                    self.source, 0, 0, n.name, f"transposing by {semitones} leaves the MIDI range"
                )
            moved.append(replace(n, pitch=pitch))
        return Score(tuple(moved), self.source)

    def at_tempo(self, factor: float) -> Score:
        """The piece played ``factor`` times as fast (2.0 = twice the tempo): every
        onset and length divided by ``factor``. ValueError unless 0.1 <= factor <= 10."""
        if not (math.isfinite(factor) and 0.1 <= factor <= 10.0):
            raise InputError(f"tempo factor must be 0.1..10 (1 = as written), got {factor}")
        return Score(
            tuple(
                replace(n, onset=n.onset / factor, duration=n.duration / factor) for n in self.notes
            ),
            self.source,
        )


def make_score(notes: list[Note], source: str) -> Score:
    """Sort ``notes`` into a Score; ScoreError if there are none."""
    if not notes:
        raise ScoreError(source, 1, 1, "", "the score has no notes; write at least one")
    return Score(tuple(sorted(notes, key=lambda n: (n.onset, n.pitch))), source)


def parse_pitch(text: str) -> int | None:
    """``"C4"``, ``"c#4"``, ``"Bb3"``, ``"A-1"`` -> MIDI number; None if it is not
    a note name or is outside 0..127 (the scene's ``note_number``, one reading of names)."""
    if not isinstance(text, str):
        return note_number(text)  # refused there: not a string
    return note_number(text) if text == text.strip() else None
