"""Instruments on the table (001's music task): a xylophone and drums."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from .._errors import InputError

F64 = NDArray[np.float64]
NOTE_NAMES = ("C", "C#", "D", "D#", "E", "F", "F#", "G", "G#", "A", "A#", "B")


def note_name(note: int) -> str:
    """MIDI note number to a name: 60 -> ``"C4"``."""
    return f"{NOTE_NAMES[note % 12]}{note // 12 - 1}"


@dataclass(frozen=True, eq=False)
class Xylophone:
    """Bars in a row, one semitone apart, centres on a straight line.

    Attributes:
        first_bar, last_bar: centre of the top face of the lowest and highest bar
            [m], shape (3,).
        lowest_note: MIDI note of the first bar (60 = C4).
        bar_count: number of bars (>= 2).
        bar_size: (length across the row, width along the row) of a bar [m].
    """

    name: str
    first_bar: F64
    last_bar: F64
    lowest_note: int
    bar_count: int
    bar_size: tuple[float, float]

    @property
    def notes(self) -> range:
        """The MIDI notes it plays."""
        return range(self.lowest_note, self.lowest_note + self.bar_count)

    def bar_top(self, note: int) -> F64:
        """Centre of the top face of the bar for MIDI ``note`` [m], shape (3,).

        Raises:
            ValueError: the xylophone has no such note (the message names its range).
        """
        if note not in self.notes:
            lo, hi = note_name(self.notes[0]), note_name(self.notes[-1])
            raise InputError(
                f"{self.name} has no note {note} ({note_name(note)}); it plays {lo}..{hi} "
                f"(MIDI {self.notes[0]}..{self.notes[-1]})"
            )
        k = (note - self.lowest_note) / (self.bar_count - 1)
        top: F64 = self.first_bar + k * (self.last_bar - self.first_bar)
        return top


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
