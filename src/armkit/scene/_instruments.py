"""Instruments on the table (001's music task): a xylophone and drums."""

from __future__ import annotations

import math
import re
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from .._errors import InputError
from .._inputs import array, brief, is_number, mm, shown
from .._primitives import RGB, Box, Cylinder, Primitive
from .._primitives import pose as placed
from .._terminal import count
from ._fields import MAX_MM
from ._object import Placed, Solid, Support
from ._rect import Rect

F64 = NDArray[np.float64]
BAR_COLOURS: tuple[RGB, ...] = ((190, 140, 70), (150, 100, 50))  # naturals, sharps (darker)
DRUM_COLOUR: RGB = (180, 40, 40)
NOTE_NAMES = ("C", "C#", "D", "D#", "E", "F", "F#", "G", "G#", "A", "A#", "B")
_PITCH = re.compile(r"([A-Ga-g])([#b]?)(-?\d)")
MIDI_HIGHEST = 127  # MIDI notes are 0..127
MAX_SIZE = MAX_MM / 1000.0  # [m] a bar's or drum's size, as any size in a scene (10 m)


def midi_note(note: object, name: str = "note") -> int:
    """``note`` checked to be a MIDI note number, an integer (60 = C4), not a bool
    (InputError naming ``name`` otherwise; a note name points to ``parse_pitch``)."""
    if isinstance(note, int | np.integer) and not isinstance(note, bool):
        return int(note)
    hint = "; for a note name use armkit.music.parse_pitch" if isinstance(note, str) else ""
    raise InputError(
        f"{name} must be a MIDI note number, an integer (60 = C4), got {shown(note)}{hint}"
    )


def _note_0_127(note: object, name: str, example: str = "60 = C4") -> int:
    """``note`` checked to be a MIDI note number in 0..127 (InputError naming ``name``)."""
    n = midi_note(note, name)
    if not 0 <= n <= MIDI_HIGHEST:
        raise InputError(f"{name} must be a MIDI note 0..{MIDI_HIGHEST} ({example}), got {n}")
    return n


def _size(value: object, name: str) -> float:
    """A size [m] > 0 and at most ``MAX_SIZE`` (InputError naming ``name`` in m and mm,
    with the likely slip of millimetres given as metres)."""
    v = float(value) if is_number(value) else math.nan  # type: ignore[arg-type]
    if 0.0 < v <= MAX_SIZE:  # NaN fails
        return v
    allowed = f"{name} must be more than 0 and at most {MAX_SIZE:g} m, given in metres"
    if not math.isfinite(v):
        raise InputError(f"{allowed}, got {shown(value)}")
    slip = f"; is {shown(v)} in mm? give {shown(v / 1000.0)}" if v > MAX_SIZE else ""
    raise InputError(f"{allowed}, got {shown(v)} m ({brief(v * 1000.0)} mm){slip}")


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
        """Refuse what no xylophone is (InputError naming the field): notes not ascending
        MIDI notes 0..127 each once, shapes that do not fit, a value not finite, a bar
        size not more than 0 and at most 10 m."""
        n = len(self.notes)
        for k, note in enumerate(self.notes):
            _note_0_127(note, f"{self.name}: notes[{k}]")
        if n == 0 or list(self.notes) != sorted(set(self.notes)):
            raise InputError(f"{self.name}: notes must be ascending, each once, got {self.notes}")
        shapes = (np.shape(self.tops), np.shape(self.sizes), np.shape(self.rows))
        if shapes != ((n, 3), (n, 2), (n,)):
            raise InputError(f"{self.name}: tops, sizes, rows need shapes (N, 3), (N, 2), (N,)")
        array(self.tops, f"{self.name}: tops", ((n, 3),), "m")
        array(self.rows, f"{self.name}: rows", ((n,),), "rad")
        for k, size in enumerate(array(self.sizes, f"{self.name}: sizes", ((n, 2),), "m")):
            _size(float(size[0]), f"{self.name}: the length of bar {k}")
            _size(float(size[1]), f"{self.name}: the width of bar {k}")

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
        ``bar_size`` = (length across the row, width along the row) [m], each more than
        0 and at most 10 m.

        Raises:
            InputError: a note outside MIDI 0..127 (the highest bar's included), a
                ``bar_count`` not a whole number >= 1, or a point or size that is not one.
        """
        lowest = _note_0_127(lowest_note, f"{name}: lowest_note")
        if not (isinstance(bar_count, int | np.integer) and not isinstance(bar_count, bool)):
            raise InputError(
                f"{name}: bar_count must be a whole number >= 1, got {shown(bar_count)}"
            )
        if not 1 <= bar_count <= MIDI_HIGHEST + 1 - lowest:
            raise InputError(
                f"{name}: bar_count must be 1..{MIDI_HIGHEST + 1 - lowest} from lowest_note "
                f"{lowest} ({note_name(lowest)}): the highest bar must be a MIDI note 0.."
                f"{MIDI_HIGHEST}, got {int(bar_count)}"
            )
        first = array(first_bar, f"{name}: first_bar", ((3,),), "m")
        last = array(last_bar, f"{name}: last_bar", ((3,),), "m")
        size = array(bar_size, f"{name}: bar_size", ((2,),), "m")
        _size(float(size[0]), f"{name}: bar_size[0] (the length across the row)")
        _size(float(size[1]), f"{name}: bar_size[1] (the width along the row)")
        bar_count = int(bar_count)
        share = np.linspace(0.0, 1.0, bar_count)[:, None]
        row = math.atan2(float(last[1] - first[1]), float(last[0] - first[0]))
        return cls(
            name,
            tuple(range(lowest, lowest + bar_count)),
            first + share * (last - first),
            np.tile(size, (bar_count, 1)),
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

    def solids(self) -> tuple[Solid, ...]:
        """None: playing strikes the bars on purpose."""
        return ()

    def supports(self, foot: Rect) -> tuple[Support, ...]:
        """None: nothing is put down on a xylophone."""
        return ()

    def listed(self, scene: Placed) -> tuple[str, str]:
        """Its bars: each note and its top centre."""
        bars = ", ".join(f"{note_name(n)} {mm(self.bar_top(n))}" for n in self.notes)
        return "instruments", (
            f"{self.name}: xylophone, {count(len(self.notes), 'bar')} (note, top centre): {bars}"
        )

    def primitives(self, scene: Placed) -> list[Primitive]:
        """Its bars (naturals light, sharps dark), each at its place."""
        shapes: list[Primitive] = []
        for note in self.notes:
            length, width = self.bar_size(note)
            size = np.array([length, width * 0.9, 0.01])
            top = self.bar_top(note) - np.array([0.0, 0.0, 0.005])
            T = placed(top, self.bar_row(note) + math.pi / 2)
            colour = BAR_COLOURS[int(note % 12 in (1, 3, 6, 8, 10))]
            shapes.append(Box(f"/scene/{self.name}/bar_{note}", size, T, colour))
        return shapes


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

    def __post_init__(self) -> None:
        """Refuse what no drum is (InputError naming the field; values are kept as given):
        a position not three finite numbers [m], a radius not more than 0 and at most
        10 m, a top_z not a finite number within 10 m, a note not a MIDI note 0..127."""
        array(self.position, f"{self.name}: position", ((3,),), "m")
        _size(self.radius, f"{self.name}: radius")
        if not (is_number(self.top_z) and abs(self.top_z) <= MAX_SIZE):  # NaN fails too
            raise InputError(
                f"{self.name}: top_z must be a height within {MAX_SIZE:g} m of the table, given "
                f"in metres, got {shown(self.top_z)}"
            )
        _note_0_127(self.note, f"{self.name}: note", "General MIDI percussion: 38 = snare")

    @property
    def head(self) -> F64:
        """Centre of the head [m], shape (3,)."""
        return np.array([self.position[0], self.position[1], self.top_z])

    def solids(self) -> tuple[Solid, ...]:
        """None: playing strikes the head on purpose."""
        return ()

    def supports(self, foot: Rect) -> tuple[Support, ...]:
        """None: nothing is put down on a drum."""
        return ()

    def listed(self, scene: Placed) -> tuple[str, str]:
        """Its note and head."""
        return "instruments", (
            f"{self.name}: drum (note {self.note}), head r {self.radius * 1000:.1f} mm at "
            f"{mm(self.head)}"
        )

    def primitives(self, scene: Placed) -> list[Primitive]:
        """Its body, up to the head."""
        height = float(self.head[2] - self.position[2])
        centre = self.position + np.array([0.0, 0.0, height / 2])
        return [Cylinder(f"/scene/{self.name}", self.radius, height, placed(centre), DRUM_COLOUR)]


Instrument = Xylophone | Drum
