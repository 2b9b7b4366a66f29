"""The tunes shipped in examples/music: they load, the MIDI file is what its
generator writes, and the note list has its tempo change."""

from __future__ import annotations

import importlib.util
import io
from pathlib import Path

import pytest

from armkit.music import load_score

TUNES = Path(__file__).parent.parent.parent / "examples" / "music"


@pytest.mark.parametrize(
    ("name", "count", "drums"),
    [("ode_to_joy.mid", 16, [38]), ("twinkle.rtttl", 14, []), ("frere_jacques.txt", 28, [38])],
)
def test_shipped_tunes_load(name: str, count: int, drums: list[int]) -> None:
    score = load_score(TUNES / name)
    assert len(score.notes) == count
    assert all(72 <= n.pitch <= 95 for n in score.notes if not n.drum)  # C5..B6
    assert [n.pitch for n in score.notes if n.drum] == drums


def test_the_midi_file_is_what_its_generator_writes() -> None:
    spec = importlib.util.spec_from_file_location("make_ode_to_joy", TUNES / "make_ode_to_joy.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    out = io.BytesIO()
    module.build().save(file=out)
    assert out.getvalue() == (TUNES / "ode_to_joy.mid").read_bytes()


def test_ode_to_joy_slows_down_in_its_last_bar() -> None:
    notes = [n for n in load_score(TUNES / "ode_to_joy.mid").notes if not n.drum]
    assert notes[1].onset - notes[0].onset == pytest.approx(0.6)  # 100 bpm
    assert notes[-1].onset - notes[-2].onset == pytest.approx(0.5 * 60 / 70)  # 70 bpm


def test_frere_jacques_changes_tempo() -> None:
    notes = load_score(TUNES / "frere_jacques.txt").notes
    assert notes[1].onset == pytest.approx(60 / 72)
    assert notes[-1].duration == pytest.approx(2 * 60 / 56)  # the closing snare, a half note at 56
