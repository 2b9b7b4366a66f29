"""The three score formats read into one Score: times, pitches, loudness, drums, errors."""

from __future__ import annotations

from pathlib import Path

import pytest

from armkit import ArmkitError
from armkit.music import (
    Note,
    Score,
    ScoreError,
    load_score,
    midi_bytes,
    note_name,
    parse_midi,
    parse_notelist,
    parse_pitch,
    parse_rtttl,
)
from armkit.music._midi import mido_module


def test_pitch_names_round_trip() -> None:
    assert parse_pitch("C4") == 60 and parse_pitch("A4") == 69
    assert parse_pitch("c#4") == 61 and parse_pitch("Bb3") == 58 and parse_pitch("C-1") == 0
    assert parse_pitch("H4") is None and parse_pitch("G9") == 127 and parse_pitch("G#9") is None
    assert all(parse_pitch(note_name(p)) == p for p in range(128))


def test_notelist_times_follow_tempo_changes() -> None:
    score = parse_notelist("tempo 120\nC4 q  E4 e  G4 e  R q\ntempo 60\nC5 h.", "t.txt")
    assert [n.pitch for n in score.notes] == [60, 64, 67, 72]
    assert [n.onset for n in score.notes] == [0.0, 0.5, 0.75, 1.5]
    assert score.notes[-1].duration == 3.0  # a dotted half at 60 bpm
    assert score.notes[0].where == "t.txt:2:1"


def test_notelist_loudness_drums_and_triplets() -> None:
    score = parse_notelist("pp C4 e3 velocity 120 snare e3 d42 e3 ff E4 q", "t.txt")
    assert [(n.velocity, n.drum) for n in score.notes] == [
        (33, False),
        (120, True),
        (120, True),
        (112, False),
    ]
    assert score.notes[1].pitch == 38 and score.notes[2].pitch == 42
    assert score.notes[3].onset == pytest.approx(0.5)  # three triplet eighths = one beat


def test_rtttl_defaults_dots_and_octaves() -> None:
    score = parse_rtttl("tune:d=4,o=5,b=120:8e,p,c.6,2a4.", "t.rtttl")
    assert [n.pitch for n in score.notes] == [76, 84, 69]
    assert [n.onset for n in score.notes] == [0.0, 0.75, 1.5]
    assert [n.duration for n in score.notes] == [0.25, 0.75, 1.5]


def test_rtttl_without_settings_uses_the_standard_defaults() -> None:
    score = parse_rtttl("x::c", "t.rtttl")  # d=4, o=6, b=63
    assert score.notes[0].pitch == 84 and score.notes[0].duration == pytest.approx(60 / 63)


def test_midi_round_trip_keeps_times_and_drums() -> None:
    written = parse_notelist("tempo 100 C4 q f snare e E4 e. R s G4 w", "t.txt")
    read = parse_midi(midi_bytes(written, bpm=100), "t.mid")
    assert [(n.pitch, n.drum, n.velocity) for n in read.notes] == [
        (n.pitch, n.drum, n.velocity) for n in written.notes
    ]
    for a, b in zip(read.notes, written.notes, strict=True):
        assert a.onset == pytest.approx(b.onset, abs=1e-3)
        assert a.duration == pytest.approx(b.duration, abs=1e-3)


def _midi_with_tempo_map() -> bytes:
    """Four quarter notes; the tempo halves after the second; note-offs as velocity 0."""
    mido = mido_module()
    track = mido.MidiTrack()
    track.append(mido.MetaMessage("set_tempo", tempo=500_000))  # 120 bpm
    for i, note in enumerate([60, 62, 64, 65]):
        if i == 2:
            track.append(mido.MetaMessage("set_tempo", tempo=1_000_000))  # 60 bpm
        track.append(mido.Message("note_on", note=note, velocity=90, time=0))
        track.append(mido.Message("note_on", note=note, velocity=0, time=480))
    track.append(mido.Message("note_on", channel=9, note=36, velocity=100, time=0))
    track.append(mido.Message("note_off", channel=9, note=36, time=240))
    import io

    out = io.BytesIO()
    mido.MidiFile(type=1, ticks_per_beat=480, tracks=[track]).save(file=out)
    return out.getvalue()


def test_midi_applies_the_tempo_map_velocity_zero_and_channel_10() -> None:
    score = parse_midi(_midi_with_tempo_map(), "t.mid")
    assert [n.onset for n in score.notes] == pytest.approx([0.0, 0.5, 1.0, 2.0, 3.0])
    assert [n.duration for n in score.notes] == pytest.approx([0.5, 0.5, 1.0, 1.0, 0.5])
    assert [n.drum for n in score.notes] == [False, False, False, False, True]


def test_transpose_and_tempo_scaling() -> None:
    score = parse_notelist("C4 q snare q", "t.txt")
    up = score.transposed(12)
    assert [n.pitch for n in up.notes] == [72, 38]  # drums are not transposed
    fast = score.at_tempo(2.0)
    assert [n.onset for n in fast.notes] == [0.0, 0.25]
    with pytest.raises(ValueError, match=r"a factor 0\.1\.\.4 "):
        score.at_tempo(0.0)
    with pytest.raises(ScoreError, match="MIDI range"):
        parse_notelist("G9 q", "t.txt").transposed(1)


@pytest.mark.parametrize(
    ("text", "where", "token"),
    [
        ("C4 q\nE4 zz", "t.txt:2:4:", "'zz'"),
        ("tempo 120\n  H4 q", "t.txt:2:3:", "'H4'"),
        ("C4\nq", "t.txt:1:1:", "'C4'"),
        ("tempo fast C4 q", "t.txt:1:7:", "'fast'"),
        ("velocity 300 C4 q", "t.txt:1:10:", "'300'"),
        ("# nothing\nR w", "t.txt:1:1:", "end of input"),
    ],
)
def test_notelist_errors_name_file_line_column_token(text: str, where: str, token: str) -> None:
    with pytest.raises(ScoreError) as err:
        parse_notelist(text, "t.txt")
    assert str(err.value).startswith(where) and token in str(err.value)
    assert isinstance(err.value, ArmkitError) and isinstance(err.value, ValueError)


@pytest.mark.parametrize(
    ("text", "where", "token"),
    [
        ("tune:d=4,o=5,b=120:c,\n  x", "t.rtttl:2:3:", "'x'"),
        ("tune:d=5:c", "t.rtttl:1:6:", "'d=5'"),
        ("tune:q=1:c", "t.rtttl:1:6:", "'q=1'"),
        ("tune:d=4:c,,d", "t.rtttl:1:12:", "','"),
        ("tune:d=4:64c", "t.rtttl:1:10:", "'64c'"),
        ("just a name", "t.rtttl:1:1:", "'just a name'"),
    ],
)
def test_rtttl_errors_name_file_line_column_token(text: str, where: str, token: str) -> None:
    with pytest.raises(ScoreError) as err:
        parse_rtttl(text, "t.rtttl")
    assert str(err.value).startswith(where) and token in str(err.value)


def test_midi_errors_name_the_chunk_and_byte() -> None:
    data = _midi_with_tempo_map()
    with pytest.raises(
        ScoreError, match=r"^t\.mid: byte \d+ \(track 1\): not a readable MIDI file: it ends"
    ):
        parse_midi(data[:-6], "t.mid")
    with pytest.raises(ScoreError, match=r"^t\.mid: byte \d+ \(the header\): .*MThd"):
        parse_midi(b"RIFF" + data[4:], "t.mid")


def test_load_score_by_suffix(tmp_path: Path) -> None:
    (tmp_path / "a.txt").write_text("C4 q")
    (tmp_path / "a.rtttl").write_text("a:d=4,o=4,b=120:c")
    (tmp_path / "a.mid").write_bytes(midi_bytes(Score((Note(0.0, 60, 80, 0.5),))))
    for name in ("a.txt", "a.rtttl", "a.mid"):
        assert load_score(tmp_path / name).notes[0].pitch == 60
    assert load_score(tmp_path / "a.txt", transpose=-12).notes[0].pitch == 48
    with pytest.raises(ScoreError, match=r"a\.doc: unknown score format; .*\.mid"):
        load_score(tmp_path / "a.doc")
    with pytest.raises(ScoreError, match=r"a\.txt: transpose is whole semitones, got 'x'"):
        load_score(tmp_path / "a.txt", transpose="x")  # type: ignore[arg-type]
    with pytest.raises(ScoreError, match="a score is a file path"):
        load_score(5)  # type: ignore[arg-type]
    with pytest.raises(ScoreError, match=r"missing\.txt: cannot read the file: [^()]*$"):
        load_score(tmp_path / "missing.txt")  # the whole file: no line, column or token
    with pytest.raises(ScoreError, match=r"missing\.mid: cannot read the file: [^()]*$"):
        load_score(tmp_path / "missing.mid")
    (tmp_path / "b.txt").write_bytes(b"C4 q\nE4 \xff q")
    with pytest.raises(ScoreError, match=r"b\.txt:2:4: not UTF-8"):
        load_score(tmp_path / "b.txt")
