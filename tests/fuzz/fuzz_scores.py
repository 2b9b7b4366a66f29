"""Scores played on the ``xylophone`` scene: MIDI files, RTTTL tunes and note lists."""

from __future__ import annotations

import random
import struct

from fuzz_engine import Step
from fuzz_language import Language, files, last, one


def _play(rng: random.Random, name: str, data: bytes) -> tuple[Step, ...]:
    play = ("--scene", "xylophone", "play", name)
    return (one(*play, "--dry-run"), one(*play, when="refused"))


def _chunk(kind: bytes, body: bytes, length: int | None = None) -> bytes:
    return kind + struct.pack(">I", len(body) if length is None else length) + body


def _midi(
    tracks: list[bytes], kind: int = 1, division: int = 480, count: int | None = None
) -> bytes:
    header = _chunk(
        b"MThd", struct.pack(">HHH", kind, len(tracks) if count is None else count, division)
    )
    return header + b"".join(_chunk(b"MTrk", t) for t in tracks)


def _vlq(value: int) -> bytes:
    out = [value & 0x7F]
    value >>= 7
    while value:
        out.append(0x80 | (value & 0x7F))
        value >>= 7
    return bytes(reversed(out))


END = b"\x00\xff\x2f\x00"
NOTE = b"\x00\x90\x48\x60" + _vlq(480) + b"\x80\x48\x00"


def _midi_grammar(rng: random.Random) -> bytes:
    """A MIDI file of random events, tempos and lengths (often wrong)."""
    tracks = []
    for _ in range(rng.randint(1, 3)):
        body = b""
        for _ in range(rng.randint(0, 40)):
            delta = _vlq(rng.choice((0, 1, 240, 480, 100_000, 0x0FFFFFFF)))
            kind = rng.random()
            if kind < 0.6:
                status = rng.choice((0x90, 0x80, 0x99, 0xB0, 0xC0, 0xE0)) | rng.randrange(16)
                body += delta + bytes([status, rng.randrange(128), rng.randrange(128)])
            elif kind < 0.75:
                tempo = rng.choice((1, 500_000, 0xFFFFFF, 0))
                body += delta + b"\xff\x51\x03" + tempo.to_bytes(3, "big")
            elif kind < 0.85:
                body += delta + b"\xf0" + _vlq(rng.choice((0, 5, 0x0FFFFFFF))) + b"\x7e\xf7"
            else:
                body += delta + bytes(rng.randrange(256) for _ in range(rng.randint(1, 6)))
        tracks.append(body + END * (rng.random() < 0.9))
    return _midi(
        tracks, kind=rng.choice((0, 1, 1, 2)), division=rng.choice((480, 96, 1, 0, 0xE728))
    )


MIDI_NASTY = (
    ("no bytes", b""),
    ("a header only", _midi([])),
    ("65 535 tracks announced, none there", _midi([], count=65_535)),
    (
        "a chunk of 4 GiB announced",
        b"MThd\x00\x00\x00\x06\x00\x01\x00\x01\x01\xe0MTrk\xff\xff\xff\xff" + NOTE,
    ),
    ("a delta of 2**28 ticks", _midi([_vlq(0x0FFFFFFF) + b"\x90\x48\x60" + END])),
    (
        "the slowest tempo, then a note",
        _midi([b"\x00\xff\x51\x03\xff\xff\xff" + _vlq(0x0FFFFFFF) + NOTE + END]),
    ),
    ("a tempo of 0", _midi([b"\x00\xff\x51\x03\x00\x00\x00" + NOTE + END])),
    ("a division of 0", _midi([NOTE + END], division=0)),
    ("SMPTE time", _midi([NOTE + END], division=0xE728)),
    ("100 000 notes", _midi([NOTE * 100_000 + END])),
    ("100 000 notes at once", _midi([b"\x00\x90\x48\x60" * 100_000 + END])),
    ("a sysex of 2**28 bytes announced", _midi([b"\x00\xf0" + _vlq(0x0FFFFFFF) + b"\xf7" + END])),
    ("running status with no status", _midi([b"\x00\x48\x60" + END])),
    ("a type 2 file", _midi([NOTE + END], kind=2)),
    ("a MIDI file of text", b"tempo 120\nC4 q\n"),
)  # fmt: skip
# cheap cases first: `make test` runs the first few
MIDI_NASTY = last(MIDI_NASTY, ["100 000 notes", "100 000 notes at once"])

MIDI = Language(
    name="MIDI",
    suffix=".mid",
    seeds={**files("examples/music/*.mid"), "grammar.mid": _midi([NOTE * 8 + END])},
    nasty=MIDI_NASTY,
    words=("\x90", "\xff\x51\x03", "MTrk", "MThd", "\xf0", "\x00\xff\x2f\x00", "\xff\xff\xff\xff"),
    nesting=None,
    steps=_play,
    grammar=_midi_grammar,
)

RTTTL_WORDS = (
    ":", ",", "d=4", "o=5", "b=120", "b=0", "b=1000", "d=3", "o=9", "8e", "c", "p", "c#.6",
    "2a4.", "64c", "32g#7", "1b8", "99999999999999c", "d=" + "9" * 400, "b=1e400", ".", "#",
)  # fmt: skip
RTTTL_NASTY = (
    ("a name of a million characters", b"x" * 1_000_000 + b":d=4,o=5,b=120:c\n"),
    ("100 000 notes", b"t:d=4,o=5,b=1000:" + b",".join([b"32c"] * 100_000) + b"\n"),
    ("a tempo of 5000 digits", b"t:d=4,o=5,b=" + b"9" * 5000 + b":c,d\n"),
    ("a tempo of 0", b"t:d=4,o=5,b=0:c,d\n"),
    ("a duration of 5000 digits", b"t:d=4,o=5,b=120:" + b"9" * 5000 + b"c\n"),
    ("colons only", b":" * 100_000),
    ("commas only", b"t:d=4,o=5,b=120:" + b"," * 1_000_000),
    ("UTF-16", "t:d=4,o=5,b=120:c,d,e".encode("utf-16")),
    ("not UTF-8", b"t:d=4,o=5,b=120:c,\xff\xfe,d"),
    ("nothing", b""),
)
RTTTL = Language(
    name="RTTTL",
    suffix=".rtttl",
    seeds={
        **files("examples/music/*.rtttl"),
        "mission.rtttl": b"mission:d=16,o=6,b=95:32d,32d#,32d,32d#,32d,32d#,32d,32d#,32d,32d,"
        b"32d#,32e,32f,32f#,32g,g,8p,g,8p,a#,p,c7,p,g,8p,g,8p,f,p,f#,p\n",
    },
    nasty=RTTTL_NASTY,
    words=RTTTL_WORDS,
    nesting=None,
    steps=_play,
    grammar=lambda rng: (
        "t:"
        + ",".join(rng.choice(RTTTL_WORDS[3:8]) for _ in range(3))
        + ":"
        + ",".join(rng.choice(RTTTL_WORDS[8:]) for _ in range(rng.randint(0, 30)))
    ).encode(),
)

NOTE_WORDS = (
    "tempo", "velocity", "120", "0", "-3", "1e9", "nan", "C4", "c#4", "Bb3", "G9", "H2", "R",
    "snare", "d38", "d200", "q", "e.", "s3", "h..", "w", "x", "ff", "mp", "#", "# c", "\n",
    "tempo 1e-300", "tempo 1000", "w" + "." * 1000, "C" + "#" * 1000 + "4", "d" + "9" * 400,
)  # fmt: skip
NOTE_NASTY = (
    ("a tempo of 5000 digits", b"tempo " + b"9" * 5000 + b"\nC4 q\n"),
    ("the slowest tempo and a long note", b"tempo 1\nC5 w..........\n"),
    ("100 000 notes", b"tempo 1000\n" + b"C5 t " * 100_000),
    ("a dotted note of a million dots", b"C5 q" + b"." * 1_000_000 + b"\n"),
    ("a line of a million characters", b"x" * 1_000_000 + b"\n"),
    ("NaN and infinity", b"tempo nan\nvelocity inf\nC4 q\ntempo -inf\n"),
    ("UTF-16", "tempo 120\nC5 q\n".encode("utf-16")),
    ("not UTF-8", b"tempo 120\nC5 q \xff\n"),
    ("nothing", b""),
)
NOTELIST = Language(
    name="note lists",
    suffix=".txt",
    seeds=files("examples/music/*.txt", "examples/scripts/ode.txt"),
    nasty=NOTE_NASTY,
    words=NOTE_WORDS,
    nesting=None,
    steps=_play,
    grammar=lambda rng: " ".join(
        rng.choice(NOTE_WORDS) for _ in range(rng.randint(1, 60))
    ).encode(),
)
