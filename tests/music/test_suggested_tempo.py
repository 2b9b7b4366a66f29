"""A piece too fast is refused with a tempo that plays: the fastest one (to 0.01) the
planner itself plays every note at, found by bisection with the planner's own test. It
was an estimate from the late notes' time ratios, often refused in turn (t.txt: 0.53,
then 0.46; ode_to_joy at 3: 1.47, then 3 late notes; twinkle: 1.14, then 1.02). Also:
``plan_play`` plans and refuses the job on the model alone exactly as ``play`` does on
an arm (what ``armkit check`` plans a script's ``play`` with)."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from armkit import Arm
from armkit.arm import Start
from armkit.model import load_model
from armkit.music import PerformanceError, load_score, plan_play, play
from armkit.music._performance import fastest_tempo
from armkit.scene import load_scene
from armkit.sim import World

TUNES = Path(__file__).parents[2] / "examples" / "music"
SCENE = load_scene("xylophone")
# at 240 bpm: played at the servos' own limits, the arms play it written at 120 (issue 28)
TUNE = "tempo 240 mf\nC5 q E5 e G5 e R q C6 q\nsnare q F#5 q. D5 e3 D5 e3 D5 e3\n"


@pytest.fixture(scope="module")
def t_txt(tmp_path_factory: pytest.TempPathFactory) -> Path:
    path = tmp_path_factory.mktemp("tune") / "t.txt"
    path.write_text(TUNE)
    return path


def _refused(arm: Arm, tune: Path, tempo: float) -> PerformanceError:
    with pytest.raises(PerformanceError) as err:
        play(arm, SCENE, tune, tempo=tempo, dry_run=True)
    return err.value


@pytest.mark.parametrize(
    ("arm_name", "tune", "tempo"),
    [
        ("openmanipulator_x", "t.txt", 1.0),
        ("openmanipulator_x", "ode_to_joy.mid", 3.0),
        ("openmanipulator_x", "twinkle.rtttl", 3.0),
        ("lynx6", "t.txt", 1.0),
        ("lynx6", "ode_to_joy.mid", 4.0),
    ],
)
def test_the_suggested_tempo_plays_and_is_the_fastest_that_does(
    arm_name: str, tune: str, tempo: float, t_txt: Path
) -> None:
    path = t_txt if tune == "t.txt" else TUNES / tune
    with Arm(arm_name, "sim", world=World(), scene=SCENE) as arm:
        err = _refused(arm, path, tempo)
        suggested = err.tempo
        assert suggested is not None and f"(--tempo {suggested * 100:g} plays it)" in str(err)
        assert suggested == round(suggested, 2)  # to 0.01
        played = play(arm, SCENE, path, tempo=suggested, dry_run=True)  # not refused
        assert played.performance.feasible and played.performance.tempo == suggested
        _refused(arm, path, round(suggested + 0.01, 2))  # the next hundredth does not play


def test_played_at_its_suggestion_every_note_is_heard_on_the_beat(t_txt: Path) -> None:
    world = World()
    with Arm("openmanipulator_x", "sim", world=world, scene=SCENE) as arm:
        suggested = _refused(arm, t_txt, 1.0).tempo
        assert suggested is not None
        played = play(arm, SCENE, t_txt, tempo=suggested)
    assert [c.note for c in played.contacts] == [n.pitch for n in load_score(t_txt).notes]
    assert played.stats is not None and not played.stats.missed and not played.stats.extra
    assert played.stats.max < 5e-3


def test_bisection_returns_only_a_tempo_it_tried_and_that_played() -> None:
    tried: list[float] = []

    def plays(tempo: float) -> bool:
        tried.append(tempo)
        return tempo <= 0.537

    assert fastest_tempo(plays, 3.0) == 0.53
    assert len(tried) <= 9 and all(0.1 <= t < 3.0 for t in tried)
    tried.clear()
    assert fastest_tempo(plays, 1.0, guess=0.53) == 0.53 and len(tried) <= 8
    assert fastest_tempo(lambda t: False, 1.0) is None  # not even 0.1 plays
    assert fastest_tempo(lambda t: True, 0.1) is None  # nothing slower to try
    assert fastest_tempo(lambda t: True, 0.53) == 0.52  # below the tempo refused


def test_no_tempo_is_suggested_for_a_note_out_of_reach(tmp_path: Path) -> None:
    tune = tmp_path / "t.txt"
    tune.write_text("tempo 400\nC5 s C6 s C5 s C6 s\n")
    T = np.eye(4)
    T[0, 3] = -0.5  # the arm half a metre behind the instruments: none in reach
    with pytest.raises(PerformanceError) as err:
        plan_play(load_model("openmanipulator_x"), replace(SCENE, T_world_base=T), tune)
    assert err.value.tempo is None and "no tempo brings a note into reach" in str(err.value)


@pytest.mark.parametrize("arm_name", ["openmanipulator_x", "lynx6"])
def test_plan_play_on_the_model_refuses_as_play_on_the_arm(arm_name: str, t_txt: Path) -> None:
    with Arm(arm_name, "sim", world=World(), scene=SCENE) as arm:
        q = arm.driver.read()
        on_arm = _refused(arm, t_txt, 1.0)
    with pytest.raises(PerformanceError) as on_model:
        plan_play(Start(load_model(arm_name), q), SCENE, t_txt)
    assert str(on_model.value) == str(on_arm) and on_model.value.tempo == on_arm.tempo
    with pytest.raises(PerformanceError) as scripted:
        plan_play(Start(load_model(arm_name), q), SCENE, t_txt, script=True)
    assert f"(tempo {on_arm.tempo * 100:g}% plays it)" in str(scripted.value)
