"""Notes -> the bars and drums of an instrument layout (the scene's Xylophone and Drum).

The layout is any sequence of objects shaped like the scene's ``Xylophone``
(``name``, ``notes``, ``bar_top(note)``) or ``Drum`` (``name``, ``position``,
``top_z``, ``note``); positions are in the scene's (table) frame [m].
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Protocol, runtime_checkable

import numpy as np
from numpy.typing import NDArray

from .._errors import ArmkitError
from .._terminal import count
from ._score import Note, Score, note_name

F64 = NDArray[np.float64]
SHOWN = 12  # notes listed in a message before "and N more"


@runtime_checkable
class Bars(Protocol):
    """A xylophone: one bar per note of ``notes``."""

    @property
    def name(self) -> str: ...
    @property
    def notes(self) -> Sequence[int]: ...
    def bar_top(self, note: int) -> F64:
        """Centre of the bar's top face [m], shape (3,), scene frame."""
        ...


@runtime_checkable
class DrumLike(Protocol):
    """A drum struck at the centre of its head."""

    @property
    def name(self) -> str: ...
    @property
    def position(self) -> F64: ...
    @property
    def top_z(self) -> float: ...
    @property
    def note(self) -> int: ...


Instrument = Bars | DrumLike


class RangeError(ArmkitError, ValueError):
    """Notes of a score that no instrument of the layout can play.

    Attributes:
        notes: the unplayable notes.
        transpose: a transposition [semitones] that would fit every pitched note, or None.
    """

    def __init__(self, message: str, notes: tuple[Note, ...], transpose: int | None) -> None:
        super().__init__(message)
        self.notes, self.transpose = notes, transpose


@dataclass(frozen=True)
class StrikeSpot:
    """Where one note is struck.

    Attributes:
        note: the note.
        instrument: name of the xylophone or drum.
        point: centre of the struck surface [m], shape (3,), scene frame.
    """

    note: Note
    instrument: str
    point: F64

    @property
    def key(self) -> tuple[str, int]:
        """(instrument, note): one bar or drum, as the latency table knows it."""
        return self.instrument, self.note.pitch


def map_notes(score: Score, layout: Sequence[Instrument]) -> tuple[StrikeSpot, ...]:
    """One StrikeSpot per note: pitched notes on the first xylophone that has the bar,
    drum notes on the drum with that General MIDI number.

    Raises:
        RangeError: listing every note that nothing plays, with a transposition
            that would fit (``--transpose``) when there is one.
    """
    targets, missing = [], []
    for note in score.notes:
        found = _instrument_for(note, layout)
        if found is None:
            missing.append(note)
            continue
        point = found.bar_top(note.pitch) if isinstance(found, Bars) else _drum_top(found)
        targets.append(StrikeSpot(note, found.name, np.asarray(point, dtype=np.float64).reshape(3)))
    if missing:
        raise _range_error(score, layout, tuple(missing))
    return tuple(targets)


def _instrument_for(note: Note, layout: Sequence[Instrument]) -> Instrument | None:
    for inst in layout:
        if isinstance(inst, Bars) and not note.drum and note.pitch in inst.notes:
            return inst
        if not isinstance(inst, Bars) and note.drum and inst.note == note.pitch:
            return inst
    return None


def _drum_top(drum: DrumLike) -> F64:
    x, y = np.asarray(drum.position, dtype=np.float64)[:2]
    return np.array([x, y, float(drum.top_z)])


def playable(layout: Sequence[Instrument]) -> tuple[set[int], set[int]]:
    """(pitched notes, drum notes) the layout can play."""
    bars = {n for inst in layout if isinstance(inst, Bars) for n in inst.notes}
    drums = {inst.note for inst in layout if not isinstance(inst, Bars)}
    return bars, drums


def best_transpose(score: Score, layout: Sequence[Instrument], span: int = 48) -> int | None:
    """The smallest shift [semitones] (whole octaves first) that puts every pitched
    note on a bar, or None."""
    bars, _ = playable(layout)
    pitches = {n.pitch for n in score.notes if not n.drum}
    shifts = sorted(range(-span, span + 1), key=lambda k: (k % 12 != 0, abs(k), k))
    return next((k for k in shifts if all(p + k in bars for p in pitches)), None)


def _range_error(
    score: Score, layout: Sequence[Instrument], missing: tuple[Note, ...]
) -> RangeError:
    bars, drums = playable(layout)
    listed = ", ".join(f"{n.name} at {n.onset:.2f} s" for n in missing[:SHOWN])
    more = f" and {len(missing) - SHOWN} more" if len(missing) > SHOWN else ""
    have = f"bars {note_name(min(bars))}..{note_name(max(bars))}" if bars else "no bars"
    have += f", drums {sorted(drums)}" if drums else ", no drums"
    shift = best_transpose(score, layout) if any(not n.drum for n in missing) else None
    hint = f"; transpose by {shift} semitones (--transpose {shift})" if shift else ""
    if not hint:
        hint = "; choose a piece within the range or add the instruments to the scene"
    return RangeError(
        f"{count(len(missing), 'note')} cannot be played ({listed}{more}): the layout has {have}{hint}",
        missing,
        shift,
    )
