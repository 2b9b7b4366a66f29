"""The ``#`` command lines of a simulated SSC-32U, parsed clause by clause.

Lynxmotion SSC-32U user guide: "Servo Move or Group Move" (``#<ch>P<pw>S<spd>``
... ``T<time>``; <pw> 500..2500 µs, ``P0`` turns the channel's pulse off),
"Position Offset" (``#<ch>PO<offset>``, -100..100 µs), "Discrete Output"
(``#<ch>H`` / ``#<ch>L``), "Byte Output" (``#<bank>:<value>``, bank 0..3 = pins
0-7 .. 24-31, bit 0 = the bank's lowest pin). Like the board, a pulse outside
500..2500 µs is clamped, not refused, and a clause the board cannot read is
skipped without dropping the rest of the line.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass, field

CHANNELS = 32
PULSE_RANGE = (500, 2500)  # [µs]
OFFSET_RANGE = (-100, 100)  # [µs]
Tokens = list[tuple[str, str]]


@dataclass
class HashLine:
    """What one ``#`` line asks: moves (channel, pulse µs (0 = off), speed µs/s or 0),
    offsets (channel -> µs), output levels (channel -> high), time [ms], and what was skipped."""

    moves: list[tuple[int, int, int]] = field(default_factory=list)
    offsets: dict[int, int] = field(default_factory=dict)
    levels: dict[int, bool] = field(default_factory=dict)
    time_ms: int = 0
    skipped: list[str] = field(default_factory=list)


def parse_hash_line(tokens: Tokens) -> HashLine:
    """A tokenized ``#`` line -> ``HashLine`` (see module doc)."""
    line = HashLine()
    if tokens and tokens[-1][0] == "T":
        line.time_ms, tokens = _int(tokens[-1][1]), tokens[:-1]
    starts = [i for i, (kind, _) in enumerate(tokens) if kind == "#"] + [len(tokens)]
    for begin, end in itertools.pairwise(starts):
        problem = _clause(tokens[begin:end], line)
        if problem:
            line.skipped.append(f"{problem} in {tokens[begin:end]}")
    return line


def _clause(clause: Tokens, line: HashLine) -> str:
    """Add one ``#<ch>...`` clause to ``line``; what is wrong with it, or ""."""
    kinds = [kind for kind, _ in clause]
    args = [arg for _, arg in clause]
    ch = _digits(args[0])
    if ch is None:
        return "no channel"
    level = _digits(args[1]) if len(args) > 1 else None
    if kinds[1:] == [":"] and level is not None and ch < CHANNELS // 8 and level < 256:
        line.levels.update({8 * ch + bit: bool(level >> bit & 1) for bit in range(8)})
        return ""
    if ch >= CHANNELS:
        return f"no channel {ch}"
    if kinds[1:] in (["H"], ["L"]) and not args[1]:
        line.levels[ch] = kinds[1] == "H"
        return ""
    if kinds[1:] == ["PO"] and args[1]:
        offset = _int(args[1])
        if not OFFSET_RANGE[0] <= offset <= OFFSET_RANGE[1]:
            return f"offset {offset} outside {OFFSET_RANGE}"
        line.offsets[ch] = offset
        return ""
    values = [_digits(a) for a in args[1:]]
    if kinds[1:] in (["P"], ["P", "S"]) and all(v is not None for v in values):
        pulse = values[0] or 0
        if pulse:
            pulse = min(max(pulse, PULSE_RANGE[0]), PULSE_RANGE[1])
        line.moves.append((ch, pulse, values[1] or 0 if len(values) == 2 else 0))
        return ""
    return "not a clause the board reads"


def _digits(text: str) -> int | None:
    """``text`` as a whole number if it is 1 to 9 ASCII digits (no number the board
    reads is longer; Python refuses to convert one of thousands), else None."""
    return int(text) if text.isascii() and text.isdigit() and len(text) <= 9 else None


def _int(text: str) -> int:
    try:
        return int(text)
    except ValueError:
        return 0
