"""Fuzzing the three score readers: a Score or a ScoreError that names the file, a
line and column inside the input, and the token found there; never anything else."""

from __future__ import annotations

import re

from hypothesis import given, settings
from hypothesis import strategies as st

from armkit.music import ScoreError, midi_bytes, parse_midi, parse_notelist, parse_rtttl

SETTINGS = settings(max_examples=300, derandomize=True, deadline=None)
WHERE = re.compile(r"^(?P<file>[^:]+):(?P<line>\d+):(?P<column>\d+): ")
MIDI_WHERE = re.compile(r"^(?P<file>[^:]+): (?:byte (?P<byte>\d+) \((?:the header|track \d+)\): )?")

NOTELIST_WORDS = st.sampled_from(
    [
        "tempo",
        "velocity",
        "120",
        "0",
        "-3",
        "1e9",
        "nan",
        "C4",
        "c#4",
        "Bb3",
        "G9",
        "H2",
        "R",
        "snare",
        "d38",
        "d200",
        "q",
        "e.",
        "s3",
        "h..",
        "w",
        "x",
        "ff",
        "mp",
        "#",
        "# c",
        "\n",
        "  ",
    ]
)
RTTTL_PIECES = st.sampled_from(
    [
        ":",
        ",",
        "d=4",
        "o=5",
        "b=120",
        "b=0",
        "d=3",
        "o=9",
        "8e",
        "c",
        "p",
        "c#.6",
        "2a4.",
        "64c",
        "q",
        "e..",
        ".",
        "#",
        " ",
        "\n",
        "x=1",
        "32g#7",
        "1b8",
    ]
)


def _check_text_error(err: ScoreError, text: str, source: str) -> None:
    m = WHERE.match(str(err))
    assert m is not None and m["file"] == source, str(err)
    line, column = int(m["line"]), int(m["column"])
    lines = text.splitlines() or [""]
    assert (err.line, err.column) == (line, column)
    if err.token and line >= 1 and err.token != ",":
        assert 1 <= line <= len(lines), str(err)
        assert lines[line - 1][column - 1 :].startswith(err.token[:1]), (str(err), text)


@SETTINGS
@given(st.lists(NOTELIST_WORDS, max_size=30).map(" ".join))
def test_notelist_fuzz(text: str) -> None:
    try:
        score = parse_notelist(text, "fuzz.txt")
    except ScoreError as err:
        _check_text_error(err, text, "fuzz.txt")
    else:
        assert score.notes and all(n.onset >= 0 and 0 <= n.pitch <= 127 for n in score.notes)


@SETTINGS
@given(st.text(alphabet="CDEFGABRqeshwt#b.3 0123456789\n-tempo", max_size=60))
def test_notelist_fuzz_characters(text: str) -> None:
    try:
        parse_notelist(text, "fuzz.txt")
    except ScoreError as err:
        _check_text_error(err, text, "fuzz.txt")


@SETTINGS
@given(st.lists(RTTTL_PIECES, max_size=25).map("".join))
def test_rtttl_fuzz(text: str) -> None:
    try:
        score = parse_rtttl(text, "fuzz.rtttl")
    except ScoreError as err:
        _check_text_error(err, text, "fuzz.rtttl")
    else:
        assert score.notes and all(0 <= n.pitch <= 127 for n in score.notes)


VALID_MIDI = midi_bytes(parse_notelist("tempo 90 C4 q snare e E4 e G4 h", "seed.txt"))


@SETTINGS
@given(
    st.lists(st.tuples(st.integers(0, len(VALID_MIDI) - 1), st.integers(0, 255)), max_size=6),
    st.integers(0, len(VALID_MIDI)),
)
def test_midi_fuzz(flips: list[tuple[int, int]], keep: int) -> None:
    data = bytearray(VALID_MIDI)
    for index, value in flips:
        data[index] = value
    data = data[:keep]
    try:
        score = parse_midi(bytes(data), "fuzz.mid")
    except ScoreError as err:
        m = MIDI_WHERE.match(str(err))  # a binary file: the byte, not a line and column
        assert m is not None and m["file"] == "fuzz.mid", str(err)
        assert m["byte"] is None or int(m["byte"]) == err.column
        assert 0 <= err.line <= 3 and 0 <= err.column <= len(data)
        if err.token:
            start = max(0, err.column - 4)
            assert err.token == bytes(data[start : err.column + 4]).hex(" ")
    else:
        assert score.notes and all(n.onset >= 0 and n.duration >= 0 for n in score.notes)
