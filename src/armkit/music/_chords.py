"""Chords on an arm with one mallet: notes written to sound together become one line.

``top`` keeps the highest note of each chord (a pitched note above a drum hit) and
says what it dropped; ``arpeggio`` plays a chord's notes one after another, lowest
first, evenly over the time until the next note, at most ``ARPEGGIO_S`` apart; ``refuse``
refuses a piece with a chord, naming the first.
"""

from __future__ import annotations

import warnings
from dataclasses import replace

from .._errors import ArmkitWarning, InputError
from .._inputs import shown
from ._score import Note, Score, ScoreError

CHORDS = ("top", "arpeggio", "refuse")
TOGETHER = 0.001  # [s] notes whose onsets are this close sound together
ARPEGGIO_S = 0.25  # [s] the most between a chord's notes played one after another
SHOWN = 3  # dropped notes named in the warning


class ChordWarning(ArmkitWarning):
    """Notes of chords were dropped (``--chords top``) to play one line."""


def check_chords(chords: object) -> str:
    """``chords`` if it is one of ``CHORDS``, else InputError listing them."""
    if not isinstance(chords, str) or chords not in CHORDS:
        raise InputError(f"chords must be one of {', '.join(CHORDS)}, got {shown(chords)}")
    return chords


def one_line(score: Score, chords: str = "top") -> Score:
    """``score`` with no two notes sounding together, as ``chords`` says (see the module)."""
    groups = _groups(score.notes)
    if all(len(g) == 1 for g in groups):
        return score
    mode = check_chords(chords)
    if mode == "refuse":
        first = next(g for g in groups if len(g) > 1)
        names = " and ".join(n.name for n in first)
        raise ScoreError.of_note(
            score.source, first[0],
            f"{names} sound together at {first[0].onset:.3f} s and one mallet strikes one "
            "note at a time: --chords top keeps the highest, --chords arpeggio spreads them",
        )  # fmt: skip
    if mode == "top":
        return Score(tuple(_top(score.source, groups)), score.source)
    return Score(tuple(_spread(groups)), score.source)


def _groups(notes: tuple[Note, ...]) -> list[list[Note]]:
    """The notes in onset order, those sounding together in one group each."""
    groups: list[list[Note]] = []
    for n in sorted(notes, key=lambda n: (n.onset, n.pitch)):
        if groups and n.onset - groups[-1][0].onset <= TOGETHER:
            groups[-1].append(n)
        else:
            groups.append([n])
    return groups


def _top(source: str, groups: list[list[Note]]) -> list[Note]:
    kept, dropped = [], []
    for g in groups:
        best = max(g, key=lambda n: (not n.drum, n.pitch))
        kept.append(best)
        dropped += [n for n in g if n is not best]
    if dropped:
        chords = sum(1 for g in groups if len(g) > 1)
        named = ", ".join(f"{n.name} at {n.onset:.3f} s" for n in dropped[:SHOWN])
        more = f" and {len(dropped) - SHOWN} more" if len(dropped) > SHOWN else ""
        warnings.warn(
            f"{source}: kept the highest note of {chords} chord(s), dropped {len(dropped)}: "
            f"{named}{more} (--chords arpeggio plays them one after another)",
            ChordWarning,
            stacklevel=3,
        )
    return kept


def _spread(groups: list[list[Note]]) -> list[Note]:
    out: list[Note] = []
    for k, g in enumerate(groups):
        room = groups[k + 1][0].onset - g[0].onset if k + 1 < len(groups) else g[0].duration
        gap = min(ARPEGGIO_S, room / len(g))
        out += [replace(n, onset=g[0].onset + i * gap) for i, n in enumerate(g)]
    return out
