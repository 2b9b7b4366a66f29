"""Instruments on the table (001's music task): a xylophone and drums."""

from __future__ import annotations

import math
import re
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from .._errors import InputError
from .._inputs import shown

F64 = NDArray[np.float64]
NOTE_NAMES = ("C", "C#", "D", "D#", "E", "F", "F#", "G", "G#", "A", "A#", "B")
_PITCH = re.compile(r"([A-Ga-g])([#b]?)(-?\d)")


def midi_note(note: object, name: str = "note") -> int:
    """``note`` checked to be a MIDI note number, an integer (60 = C4), not a bool
    (InputError naming ``name`` otherwise; a note name points to ``parse_pitch``)."""
    if isinstance(note, int | np.integer) and not isinstance(note, bool):
        return int(note)
    hint = "; for a note name use armkit.music.parse_pitch" if isinstance(note, str) else ""
    raise InputError(
        f"{name} must be a MIDI note number, an integer (60 = C4), got {shown(note)}{hint}"
    )


def note_name(note: int) -> str:
    """MIDI note number to a name: 60 -> ``"C4"``."""
    note = midi_note(note)
    return f"{NOTE_NAMES[note % 12]}{note // 12 - 1}"


def note_number(name: str) -> int | None:
    """A note name to its MIDI number (``"C4"`` -> 60, ``"F#5"`` -> 78, ``"Bb3"`` ->
    58), or None if ``name`` is not one or is outside MIDI 0..127 (InputError if it is
    not a string)."""
    if not isinstance(name, str):
        raise InputError(f"a note name must be a string such as 'C4' or 'F#5', got {shown(name)}")
    found = _PITCH.fullmatch(name.strip())
    if found is None:
        return None
    letter, accidental, octave = found.groups()
    number = (
        NOTE_NAMES.index(letter.upper())
        + {"#": 1, "b": -1, "": 0}[accidental]
        + 12 * (int(octave) + 1)
    )
    return number if 0 <= number <= 127 else None


@dataclass(frozen=True, eq=False)
class Xylophone:
    """Bars, one per note, each at its own place: a row interpolated from its first
    and last bar (``Xylophone.interpolated``) or given bar by bar (a chromatic
    instrument's naturals in a front row and its sharps in a raised back row).

    Attributes:
        notes: the MIDI notes, one per bar, ascending, each once; shape (N,).
        tops: centre of each bar's top face [m], shape (N, 3), in the order of ``notes``.
        sizes: (length across the row, width along the row) of each bar [m], shape (N, 2).
        rows: direction along the row at each bar [rad] in the table plane, from +x
            towards +y (a bar's length is at right angles to it), shape (N,).
    """

    name: str
    notes: tuple[int, ...]
    tops: F64
    sizes: F64
    rows: F64

    def __post_init__(self) -> None:
        n = len(self.notes)
        if n == 0 or list(self.notes) != sorted(set(self.notes)):
            raise InputError(f"{self.name}: notes must be ascending, each once, got {self.notes}")
        shapes = (self.tops.shape, self.sizes.shape, self.rows.shape)
        if shapes != ((n, 3), (n, 2), (n,)):
            raise InputError(f"{self.name}: tops, sizes, rows need shapes (N, 3), (N, 2), (N,)")

    @classmethod
    def interpolated(
        cls,
        name: str,
        first_bar: F64,
        last_bar: F64,
        lowest_note: int,
        bar_count: int,
        bar_size: tuple[float, float],
    ) -> Xylophone:
        """``bar_count`` bars one semitone apart from ``lowest_note``, their top centres
        evenly from ``first_bar`` to ``last_bar`` [m], shape (3,) each; every bar
        ``bar_size`` = (length across the row, width along the row) [m]."""
        share = np.linspace(0.0, 1.0, bar_count)[:, None]
        first, last = np.asarray(first_bar, dtype=float), np.asarray(last_bar, dtype=float)
        row = math.atan2(float(last[1] - first[1]), float(last[0] - first[0]))
        return cls(
            name,
            tuple(range(lowest_note, lowest_note + bar_count)),
            first + share * (last - first),
            np.tile(np.asarray(bar_size, dtype=float), (bar_count, 1)),
            np.full(bar_count, row),
        )

    def index(self, note: int) -> int:
        """Position of MIDI ``note``'s bar in ``notes``.

        Raises:
            InputError: the xylophone has no such note (the message names its notes).
        """
        if note in self.notes:
            return self.notes.index(note)
        lo, hi = note_name(self.notes[0]), note_name(self.notes[-1])
        chromatic = self.notes == tuple(range(self.notes[0], self.notes[-1] + 1))
        have = f"{lo}..{hi}" if chromatic else ", ".join(note_name(n) for n in self.notes)
        raise InputError(
            f"{self.name} has no note {note} ({note_name(note)}); it plays {have} "
            f"(MIDI {self.notes[0]}..{self.notes[-1]})"
        )

    def bar_top(self, note: int) -> F64:
        """Centre of the top face of the bar for MIDI ``note`` [m], shape (3,).

        Raises:
            InputError: the xylophone has no such note (the message names its notes).
        """
        top: F64 = self.tops[self.index(note)].copy()
        return top

    def bar_size(self, note: int) -> tuple[float, float]:
        """(length across the row, width along the row) of ``note``'s bar [m]."""
        length, width = self.sizes[self.index(note)]
        return float(length), float(width)

    def bar_row(self, note: int) -> float:
        """Direction along the row at ``note``'s bar [rad], from +x towards +y."""
        return float(self.rows[self.index(note)])


@dataclass(frozen=True, eq=False)
class Drum:
    """A drum: a round head at ``top_z``.

    Attributes:
        position: centre of the drum's base on the table [m], shape (3,).
        radius: of the head [m].  top_z: height of the head [m].
        note: the MIDI note (General MIDI percussion, e.g. 38 = snare) it stands for.
    """

    name: str
    position: F64
    radius: float
    top_z: float
    note: int

    @property
    def head(self) -> F64:
        """Centre of the head [m], shape (3,)."""
        return np.array([self.position[0], self.position[1], self.top_z])


Instrument = Xylophone | Drum
