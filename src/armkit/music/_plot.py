"""Planned against played onsets, as a picture (matplotlib, imported on use)."""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

from .._errors import ArmkitError
from .._files import check_output_path
from ._onsets import Contact, match, onset_stats
from ._score import note_name

PLOT_SUFFIXES = (".png", ".svg", ".pdf")


def plot_onsets(planned: Sequence[Contact], played: Sequence[Contact], path: str | Path) -> Path:
    """Save a figure: the notes against time (planned hollow, played filled) and each
    note's onset error [ms]; ``path`` ends in .png, .svg or .pdf. Returns the path."""
    out = check_output_path(path, suffixes=PLOT_SUFFIXES)
    try:
        from matplotlib.figure import Figure
    except ImportError as exc:  # pragma: no cover - the dev install has it
        raise ArmkitError("plots need matplotlib: pip install 'armkit[plot]'") from exc
    stats = onset_stats(planned, played)
    pairs = [(p, q) for p, q in match(planned, played) if q is not None]
    fig = Figure(figsize=(10, 6), layout="constrained")
    notes, errors = fig.subplots(2, 1, sharex=True)
    notes.scatter(
        [c.time for c in planned],
        [c.note for c in planned],
        facecolors="none",
        edgecolors="C0",
        label="planned",
    )
    notes.scatter(
        [c.time for c in played], [c.note for c in played], s=12, color="C1", label="played"
    )
    names = {c.note: c.instrument if c.drum else note_name(c.note) for c in [*planned, *played]}
    pitches = sorted(names)
    notes.set_yticks(pitches, [names[n] for n in pitches])
    notes.set_ylabel("note")
    notes.legend(loc="upper right")
    notes.set_title(
        f"onsets: RMS {stats.rms * 1000:.2f} ms, max {stats.max * 1000:.2f} ms, "
        f"{len(stats.missed)} missed, {len(stats.extra)} extra"
    )
    errors.axhline(0.0, color="0.6", linewidth=0.8)
    errors.stem([p.time for p, _ in pairs], [(q.time - p.time) * 1000 for p, q in pairs])
    errors.set_xlabel("time [s]")
    errors.set_ylabel("played - planned [ms]")
    fig.savefig(out)
    return out
