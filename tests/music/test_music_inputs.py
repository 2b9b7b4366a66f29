"""Bad arguments to the music functions are refused as an InputError naming the argument
and what is allowed (they were TypeErrors deep inside, or silently wrong: a transposition
of 1.5 gave pitch 77.5), and a tempo has one range, said one way, everywhere: the CLI's
``--tempo``, a script's ``tempo P%``, ``play``, ``plan_performance`` and
``Score.at_tempo`` (they were 0.1..4, 0.1..4 in %, and 0.1..10)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest

from armkit import InputError
from armkit.cli import main
from armkit.model import load_model
from armkit.music import (
    MAX_TEMPO,
    MIN_TEMPO,
    ScoreError,
    check_tempo,
    load_score,
    parse_notelist,
    plan_performance,
    time_based_predictor,
)
from armkit.scene import load_scene

SCENE = load_scene("xylophone")
MODEL = load_model("openmanipulator_x")
SCORE = parse_notelist("tempo 60 C5 q E5 q", "t.txt")
RANGE = "tempo must be a factor 0.1..4 (10%..400%) of the written speed"
TUNE = "tempo 120 mf\nC5 q E5 e G5 e R q C6 q\nsnare q F#5 q. D5 e3 D5 e3 D5 e3\n"


def _plan(**changed: Any) -> object:
    args: dict[str, Any] = {
        "score": SCORE,
        "layout": SCENE.instruments,
        "model": MODEL,
        "predictor": time_based_predictor(MODEL),
        "T_world_base": SCENE.T_world_base,
    }
    args.update(changed)
    return plan_performance(**args)


@pytest.mark.parametrize(
    ("changed", "message"),
    [
        ({"tempo": "1"}, "tempo must be a factor 0.1..4 (10%..400%) of the written speed, got '1'"),
        ({"tempo": None}, "got None"),
        ({"tempo": float("nan")}, "got nan"),
        ({"tempo": True}, "got True"),
        ({"layout": SCENE.instruments[0]}, "layout must be a tuple or list of xylophones"),
        ({"layout": [SCENE.instruments[0], "snare"]}, "layout must be a tuple or list"),
        ({"predictor": None}, "predictor must be the servos' motion model"),
        ({"rebound": 3}, "rebound must be None or a function"),
        ({"score": "t.txt"}, "score must be a Score (load_score"),
        ({"model": "openmanipulator_x"}, "model must be an ArmModel"),
        ({"start": [0.0, 0.1]}, "start must have shape (4,)"),
        ({"T_world_base": "identity"}, "T_world_base must be numbers"),
        ({"tool_length": -0.1}, "tool_length must be a finite number > 0"),
    ],
)
def test_plan_performance_names_the_bad_argument(changed: dict[str, Any], message: str) -> None:
    with pytest.raises(InputError) as err:
        _plan(**changed)
    assert message in str(err.value)


def test_one_instrument_instead_of_a_tuple_says_how_to_write_it() -> None:
    with pytest.raises(InputError, match=r"one instrument: write \(instrument,\)"):
        _plan(layout=SCENE.instruments[0])
    _plan(layout=(SCENE.instruments[0],))  # as the message says: plans


@pytest.mark.parametrize("semitones", [1.5, "2", None, True, 12.0])
def test_a_transposition_is_whole_semitones(semitones: object) -> None:
    with pytest.raises(InputError, match="semitones must be a whole number") as err:
        SCORE.transposed(semitones)  # type: ignore[arg-type]
    assert "got" in str(err.value)


def test_a_transposition_out_of_midi_names_the_note_where_it_is_written(tmp_path: Path) -> None:
    tune = tmp_path / "t.txt"
    tune.write_text(TUNE)
    with pytest.raises(ScoreError) as err:
        load_score(tune, 48)
    text = str(err.value)
    assert text.startswith(f"{tune}:2:20: transposing by 48 moves C6 (MIDI 84) to MIDI 132")
    assert "-72..43 keeps every note in" in text and ":0:0:" not in text
    assert (err.value.line, err.value.column, err.value.token) == (2, 20, "C6")


def test_the_cli_says_where_the_transposed_note_is(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    monkeypatch.setenv("ARMKIT_CONFIG_DIR", str(tmp_path / "config"))
    monkeypatch.chdir(tmp_path)
    Path("t.txt").write_text(TUNE)
    code = main(["--scene", "xylophone", "play", "t.txt", "--transpose", "48", "--dry-run"])
    err = capsys.readouterr().err
    assert code == 2 and err.startswith("armkit: error: t.txt:2:20: transposing by 48 moves C6")
    assert ":0:0:" not in err


@pytest.mark.parametrize("bad", [MIN_TEMPO - 0.01, MAX_TEMPO + 0.5, 10.0, 0.0, -1.0])
def test_every_way_of_giving_a_tempo_has_the_one_range(
    bad: float, tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    for refuse in (
        lambda: check_tempo(bad),
        lambda: SCORE.at_tempo(bad),
        lambda: _plan(tempo=bad),
    ):
        with pytest.raises(InputError) as err:
            refuse()
        assert str(err.value) == f"{RANGE}, got {bad:g}"
    monkeypatch.setenv("ARMKIT_CONFIG_DIR", str(tmp_path / "config"))
    monkeypatch.chdir(tmp_path)
    Path("t.txt").write_text(TUNE)
    percent = f"{bad * 100:g}"  # the CLI writes a tempo as a script does: a percentage
    assert main(["--scene", "xylophone", "play", "t.txt", "--tempo", percent, "--dry-run"]) == 2
    said = capsys.readouterr().err
    assert said.startswith(f"armkit: error: argument --tempo: must be 10..400 %, got {percent}")


@pytest.mark.parametrize("good", [MIN_TEMPO, MAX_TEMPO])
def test_the_ends_of_the_range_are_taken_everywhere(good: float) -> None:
    assert check_tempo(good) == good
    assert SCORE.at_tempo(good).notes[1].onset == pytest.approx(1.0 / good)
    _plan(tempo=good)  # planned (maybe infeasible), not refused
