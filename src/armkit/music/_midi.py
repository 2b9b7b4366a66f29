"""Standard MIDI files through mido (the optional ``midi`` extra).

Reading iterates the file as mido plays it: message times in seconds with the
tempo map applied. A ``note_on`` with velocity 0 is a note-off; channel 10
(mido's channel 9) is the drum kit. For a binary file a ScoreError's "line" is
the chunk (0 = the header, 1.. the tracks) and its "column" the byte offset;
the token shows the bytes there in hex.
"""

from __future__ import annotations

import io
import struct
from collections import defaultdict, deque
from pathlib import Path
from types import ModuleType
from typing import Any, cast

from .._errors import ArmkitError
from .._input_limits import MAX_SCORE_BYTES, LimitError, read_limited
from ._score import MAX_SECONDS, Note, Score, ScoreError, make_score

DRUM_CHANNEL = 9  # MIDI channel 10, counted from 0 as mido does
TICKS_PER_BEAT = 480
_MIDO_FAILURES = (OSError, EOFError, ValueError, KeyError, IndexError, TypeError, struct.error)


def mido_module() -> ModuleType:
    """mido, imported on first use; ArmkitError says how to install it."""
    try:
        import mido
    except ImportError as exc:  # pragma: no cover - the dev install has it
        raise ArmkitError("reading MIDI files needs mido: pip install 'armkit[midi]'") from exc
    return cast(ModuleType, mido)


def read_midi(path: str | Path) -> Score:
    """The notes of a MIDI file (type 0 or 1) as a Score; ScoreError on anything unreadable."""
    source = str(path)
    try:
        data = read_limited(path, MAX_SCORE_BYTES, "score")
    except LimitError as exc:
        raise ScoreError.unreadable(source, exc) from None
    return parse_midi(data, source)


def parse_midi(data: bytes, source: str = "<bytes>") -> Score:
    """The notes of MIDI file contents ``data`` (see ``read_midi``)."""
    mido = mido_module()
    buffer = io.BytesIO(data)
    try:
        midi = mido.MidiFile(file=buffer)
        if midi.ticks_per_beat <= 0:
            raise ScoreError.at_byte(
                source, 0, 12, bytes_at(data, 12), "a division of 0 ticks per beat; export it again"
            )
        messages = list(midi) if midi.type != 2 else None
    except _MIDO_FAILURES as exc:
        offset = buffer.tell()
        token = bytes_at(data, offset)
        why = (
            "it ends in the middle of a chunk"
            if isinstance(exc, EOFError)
            else str(exc) or type(exc).__name__
        )
        raise ScoreError.at_byte(
            source, chunk_at(data, offset), offset, token, f"not a readable MIDI file: {why}"
        ) from exc
    if messages is None:
        raise ScoreError.at_byte(
            source, 0, 8, bytes_at(data, 8), "type 2 (independent tracks) is not a piece to play"
        )
    score = make_score(_notes(messages, source), source)
    if score.duration > MAX_SECONDS:
        last = score.notes[-1]
        raise ScoreError(
            source, 0, 0, last.name, f"the piece runs past {MAX_SECONDS:.0f} s ({last.where})"
        )
    return score


def _notes(messages: list[Any], source: str) -> list[Note]:
    """Pair note-ons with their note-offs (first on, first off, per channel and note)."""
    sounding: defaultdict[tuple[int, int], deque[tuple[float, int, int]]] = defaultdict(deque)
    notes, time = [], 0.0
    for index, msg in enumerate(messages):
        time += float(msg.time)
        if msg.type not in ("note_on", "note_off"):
            continue
        key = (msg.channel, msg.note)
        if msg.type == "note_on" and msg.velocity > 0:
            sounding[key].append((time, msg.velocity, index))
        elif sounding[key]:
            notes.append(_note(key, sounding[key].popleft(), time, source))
    for key, left in sounding.items():
        notes.extend(_note(key, start, time, source) for start in left)
    return notes


def _note(key: tuple[int, int], start: tuple[float, int, int], end: float, source: str) -> Note:
    (channel, pitch), (onset, velocity, index) = key, start
    drum = channel == DRUM_CHANNEL
    return Note(onset, pitch, velocity, end - onset, drum, f"{source}: message {index}")


def bytes_at(data: bytes, offset: int) -> str:
    """The bytes around ``offset`` (4 before, 4 from it) in hex, as errors show them."""
    return data[max(0, offset - 4) : offset + 4].hex(" ")


def chunk_at(data: bytes, offset: int) -> int:
    """Which chunk holds byte ``offset``: 0 the header, 1.. the tracks (by their lengths)."""
    start, chunk = 0, 0
    while start + 8 <= len(data):
        length = int.from_bytes(data[start + 4 : start + 8], "big")
        if offset < start + 8 + length:
            return chunk
        start, chunk = start + 8 + length, chunk + 1
    return chunk


def midi_bytes(score: Score, bpm: float = 120.0) -> bytes:
    """A type 0 MIDI file of ``score`` at one tempo ``bpm`` [quarter notes/min], times
    rounded to 1/480 beat; drums on channel 10."""
    mido = mido_module()
    seconds_per_tick = 60.0 / bpm / TICKS_PER_BEAT
    events = []
    for n in score.notes:
        channel = DRUM_CHANNEL if n.drum else 0
        on, off = (
            round(n.onset / seconds_per_tick),
            round((n.onset + n.duration) / seconds_per_tick),
        )
        events.append(
            (on, 1, mido.Message("note_on", channel=channel, note=n.pitch, velocity=n.velocity))
        )
        events.append((max(off, on), 0, mido.Message("note_off", channel=channel, note=n.pitch)))
    track = mido.MidiTrack([mido.MetaMessage("set_tempo", tempo=mido.bpm2tempo(bpm))])
    last = 0
    for tick, _, msg in sorted(events, key=lambda e: (e[0], e[1])):
        track.append(msg.copy(time=tick - last))
        last = tick
    out = io.BytesIO()
    mido.MidiFile(type=0, ticks_per_beat=TICKS_PER_BEAT, tracks=[track]).save(file=out)
    return out.getvalue()
