"""``armkit.music.play`` on the real simulator: the OpenManipulator-X's own driver on its
simulated XM430s and the Lynx6's SSC-32 driver on a simulated SSC-32, a Listener on the
World hearing the mallet. The notes heard are the score's, in order, within the
onset tolerance (simulated time); a piece that cannot be played moves nothing."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from armkit import Arm, ArmkitError
from armkit.cli import main
from armkit.music import PerformanceError, RangeError, load_score, play
from armkit.scene import load_scene
from armkit.sim import World

TUNES = Path(__file__).parents[2] / "examples" / "music"
SCENE = load_scene("xylophone")


@pytest.mark.parametrize(("arm_name", "tempo"), [("openmanipulator_x", 1.0), ("lynx6", 1.0)])
def test_the_heard_notes_are_the_scores_on_the_beat(arm_name: str, tempo: float) -> None:
    with Arm(arm_name, "sim", world=World(), scene=SCENE) as arm:
        played = play(arm, SCENE, TUNES / "ode_to_joy.mid", tempo=tempo)
    score = load_score(TUNES / "ode_to_joy.mid")
    assert [c.note for c in played.contacts] == [n.pitch for n in score.notes]
    assert played.stats is not None
    assert played.stats.rms < 2e-3 and played.stats.max < 5e-3  # simulated time
    assert not played.stats.missed and not played.stats.extra
    # the mallet rebounds, never rests on a bar: the hobby servos' rebound turns as the
    # head reaches the top (REBOUND_LEAD), their 25 ms position loop turns it in < 40 ms
    assert 0 < max(played.dwell) <= (0.025 if arm_name == "openmanipulator_x" else 0.040)
    planned = [s.time - played.performance.offset for s in played.performance.strikes]
    assert planned == pytest.approx([n.onset / tempo for n in score.notes])


def _unmoved(arm_name: str, tune: Path, **options: object) -> ArmkitError:
    world = World()
    with Arm(arm_name, "sim", world=world, scene=SCENE) as arm:
        before, start = world.arm().q().copy(), world.now()
        with pytest.raises(ArmkitError) as caught:
            play(arm, SCENE, tune, **options)  # type: ignore[arg-type]
        assert np.array_equal(world.arm().q(), before) and world.now() == start
    return caught.value


def test_a_tune_too_fast_is_refused_with_its_late_notes_and_nothing_moves() -> None:
    err = _unmoved("openmanipulator_x", TUNES / "ode_to_joy.mid", tempo=3.0)
    assert isinstance(err, PerformanceError) and err.problems
    assert "--tempo" in str(err) and "needs" in str(err)


def test_notes_off_the_xylophone_are_refused_and_nothing_moves(tmp_path: Path) -> None:
    tune = tmp_path / "high.txt"
    tune.write_text("tempo 60\nC5 q C7 q\n")
    err = _unmoved("lynx6", tune)
    assert isinstance(err, RangeError) and [n.name for n in err.notes] == ["C7"]


@pytest.mark.parametrize(
    ("options", "problem"),
    [
        ({"tempo": 0.0}, "tempo must be"),
        ({"transpose": 100}, "transpose must be"),
        ({"on": "piano"}, "no instrument 'piano'"),
    ],
)
def test_bad_arguments_move_nothing(options: dict[str, object], problem: str) -> None:
    err = _unmoved("openmanipulator_x", TUNES / "twinkle.rtttl", **options)
    assert problem in str(err)


def test_cli_plays_and_writes_what_it_heard(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    monkeypatch.setenv("ARMKIT_CONFIG_DIR", str(tmp_path))
    wav, png = tmp_path / "out.wav", tmp_path / "onsets.png"
    args = ["--arm", "lynx6", "--scene", "xylophone.toml", "play", str(TUNES / "twinkle.rtttl")]
    assert main([*args, "--wav", str(wav), "--plot", str(png)]) == 0
    out = capsys.readouterr().out
    assert "heard 14 contacts" in out and "0 missed, 0 extra" in out
    assert wav.read_bytes()[:4] == b"RIFF" and png.read_bytes()[:4] == b"\x89PNG"


def test_cli_refuses_a_bad_output_before_playing(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    monkeypatch.setenv("ARMKIT_CONFIG_DIR", str(tmp_path))
    tune = str(TUNES / "twinkle.rtttl")
    assert main(["--scene", "xylophone", "play", tune, "--wav", str(tmp_path / "x.mp3")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "must end in .wav" in err
    assert not list(tmp_path.glob("*.toml"))  # the simulated arm was not even opened
