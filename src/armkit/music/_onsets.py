"""Contacts (what was played) against the plan (what should have been): matching,
onset errors and the per-bar latency table a calibration run gives."""

from __future__ import annotations

from collections import defaultdict
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class Contact:
    """A stick hitting a bar or drum.

    Attributes:
        time: when [s] from the start of the performance.
        instrument: name of the xylophone or drum.
        note: the bar's MIDI note (a drum's General MIDI number).
        speed: tip speed at the contact [m/s] (loudness).
        drum: True for a drum (sounds as a drum in ``render``).
    """

    time: float
    instrument: str
    note: int
    speed: float = 1.0
    drum: bool = False

    @property
    def key(self) -> tuple[str, int]:
        """(instrument, note): which bar or drum."""
        return self.instrument, self.note


@dataclass(frozen=True)
class NoteError:
    """Onset errors of one bar or drum: ``key``, ``count`` matched, ``rms`` and
    ``max`` |error| [s], ``mean`` signed error [s] (late > 0)."""

    key: tuple[str, int]
    count: int
    rms: float
    max: float
    mean: float


@dataclass(frozen=True)
class OnsetStats:
    """How close the played onsets came to the planned ones.

    Attributes:
        errors: played - planned [s] per matched note, in planned order.
        rms, max: over every matched note [s] (0 if none matched).
        missed: planned contacts with no played one near them.
        extra: played contacts that match no planned one.
        per_note: one row per bar or drum, sorted by key.
    """

    errors: tuple[float, ...]
    rms: float
    max: float
    missed: tuple[Contact, ...]
    extra: tuple[Contact, ...]
    per_note: tuple[NoteError, ...]


def match(
    planned: Sequence[Contact], played: Sequence[Contact], window: float = 0.1
) -> list[tuple[Contact, Contact | None]]:
    """Each planned contact with the nearest unused played one on the same bar within
    ``window`` [s] (None if there is none), planned contacts taken in time order."""
    free: defaultdict[tuple[str, int], list[Contact]] = defaultdict(list)
    for c in sorted(played, key=lambda c: c.time):
        free[c.key].append(c)
    pairs: list[tuple[Contact, Contact | None]] = []
    for p in sorted(planned, key=lambda c: c.time):
        options = free[p.key]
        best = min(options, key=lambda c: abs(c.time - p.time), default=None)
        if best is not None and abs(best.time - p.time) <= window:
            options.remove(best)
            pairs.append((p, best))
        else:
            pairs.append((p, None))
    return pairs


def onset_stats(
    planned: Sequence[Contact], played: Sequence[Contact], window: float = 0.1
) -> OnsetStats:
    """Onset errors of ``played`` against ``planned`` (see ``match``)."""
    pairs = match(planned, played, window)
    hit = [(p, q) for p, q in pairs if q is not None]
    errors = np.array([q.time - p.time for p, q in hit])
    used = {id(q) for _, q in hit}
    by_key: defaultdict[tuple[str, int], list[float]] = defaultdict(list)
    for (p, _), e in zip(hit, errors.tolist(), strict=True):
        by_key[p.key].append(e)
    rows = tuple(_row(key, np.array(v)) for key, v in sorted(by_key.items()))
    return OnsetStats(
        errors=tuple(errors.tolist()),
        rms=float(np.sqrt(np.mean(errors**2))) if errors.size else 0.0,
        max=float(np.max(np.abs(errors))) if errors.size else 0.0,
        missed=tuple(p for p, q in pairs if q is None),
        extra=tuple(c for c in played if id(c) not in used),
        per_note=rows,
    )


def _row(key: tuple[str, int], e: np.ndarray) -> NoteError:
    return NoteError(
        key, int(e.size), float(np.sqrt(np.mean(e**2))), float(np.max(np.abs(e))), float(np.mean(e))
    )


@dataclass(frozen=True)
class LatencyTable:
    """Constant delay [s] between the planned and the played contact, per bar or drum,
    measured in a calibration run; the planner starts each stroke that much earlier.

    Attributes:
        delays: ((instrument, note), delay [s]) pairs.
        default: delay of a bar or drum not in the table [s].
    """

    delays: tuple[tuple[tuple[str, int], float], ...] = ()
    default: float = 0.0

    def of(self, key: tuple[str, int]) -> float:
        """The delay [s] of bar or drum ``key``."""
        return dict(self.delays).get(key, self.default)

    @classmethod
    def from_run(
        cls,
        planned: Sequence[Contact],
        played: Sequence[Contact],
        previous: LatencyTable | None = None,
    ) -> LatencyTable:
        """The table that cancels the mean error of each bar in a run planned with
        ``previous`` (empty: none); bars the run missed keep their old delay; the
        default becomes the mean over every matched note."""
        before = previous or cls()
        stats = onset_stats(planned, played)
        delays = dict(before.delays)
        for row in stats.per_note:
            delays[row.key] = before.of(row.key) + row.mean
        default = before.default + (float(np.mean(stats.errors)) if stats.errors else 0.0)
        return cls(tuple(sorted(delays.items())), default)
