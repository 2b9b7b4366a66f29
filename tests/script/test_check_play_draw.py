"""``armkit check`` refuses a ``play`` or ``draw`` its job would refuse, at the job's
line, before anything moves. They passed the check (and ``run --dry-run``), then
``run`` moved the lines before them and stopped at the job: a piece too fast for the
arm ("6 of 9 notes of t.txt cannot be played"), notes a transposition puts off the
xylophone, an SVG with nothing to draw. The check now asks the jobs' own planning
functions: ``drawing.plan_on_sheet`` (what ``armkit draw svg`` refuses such a file
with), ``music.score_on`` and, from the pose the checker knows, ``music.plan_play``
(what ``armkit play`` plans with before it moves). Tempi are said as the script writes
them (``tempo 0.45`` is 0.45 %, it said ``got 0.0045000000000000005``)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from armkit import Arm
from armkit.arm import Start
from armkit.cli import main
from armkit.kinematics import ik
from armkit.model import load_model
from armkit.music import PerformanceError
from armkit.scene import load_scene
from armkit.script import ScriptCheckError, Source, check_file, run_source
from armkit.script._job_plans import plan_job
from armkit.sim import World

TUNE = "tempo 120 mf\nC5 q E5 e G5 e R q C6 q\nsnare q F#5 q. D5 e3 D5 e3 D5 e3\n"
EMPTY_SVG = '<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="100mm"></svg>\n'
TEXT_SVG = (
    '<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="100mm">'
    '<text x="10" y="50">hello</text></svg>\n'
)
LATE = (  # at twice its tempo: as written it plays (issue 28: strikes at the servos' limits)
    "5 of 9 notes of t.txt cannot be played: G5 at 0.375 s: 0.125 s after the previous note, needs"
)


def _errors(tmp_path: Path, text: str) -> list[tuple[int, int, str]]:
    (tmp_path / "t.txt").write_text(TUNE)
    (tmp_path / "empty.svg").write_text(EMPTY_SVG)
    (tmp_path / "text.svg").write_text(TEXT_SVG)
    script = tmp_path / "job.arm"
    script.write_text(text)
    result = check_file(script)
    return [(d.loc.line, d.loc.col, d.message) for d in result.diagnostics if d.severity == "error"]


def _script(job: str, scene: str = "xylophone") -> str:
    return f"scene {scene}\nmove xyz 150 0 100 pitch -90\n{job}\n"


def test_a_play_is_planned_from_the_start_as_a_script_writes_it(tmp_path: Path) -> None:
    # check and run plan a script's play alike (script._job_plans): from where the arm
    # is, tempi said as the script writes them
    (tmp_path / "t.txt").write_text(TUNE)
    model, scene = load_model("openmanipulator_x"), load_scene("xylophone")
    q = np.asarray(ik(model, np.array([0.15, 0.0, 0.10]), np.radians(-90.0), model.home).q)
    start = Start(model, q, scene=scene)
    with pytest.raises(PerformanceError) as err:
        plan_job(start, scene, "play", {"file": tmp_path / "t.txt", "tempo": 2.0})
    message = str(err.value)
    assert message.startswith(LATE.replace("t.txt", str(tmp_path / "t.txt")))
    assert "(tempo 102% plays it)" in message and "--tempo" not in message
    played = plan_job(start, scene, "play", {"file": tmp_path / "t.txt", "tempo": 1.02})
    assert played.plan is not None and played.plan.seconds > 0.0


@pytest.mark.parametrize("job", ["play t.txt tempo 200%", "play t.txt tempo 150%"])
def test_a_piece_too_fast_for_the_arm_is_an_error_at_its_line(tmp_path: Path, job: str) -> None:
    errors = _errors(tmp_path, _script(job))
    assert [(line, col) for line, col, _ in errors] == [(3, 1)]
    assert "notes of" in errors[0][2] and "cannot be played" in errors[0][2]
    assert "plays it)" in errors[0][2]


def test_run_refuses_a_piece_too_fast_before_the_first_move(tmp_path: Path) -> None:
    (tmp_path / "t.txt").write_text(TUNE)
    world = World()
    with Arm("openmanipulator_x", "sim", world=world, scene=load_scene("xylophone")) as arm:
        before, start = world.arm().q().copy(), world.now()
        with pytest.raises(ScriptCheckError, match="cannot be played"):
            run_source(arm, Source("job.arm", _script("play t.txt tempo 200%")), base_dir=tmp_path)
        assert np.array_equal(world.arm().q(), before) and world.now() == start


def test_notes_a_transposition_puts_off_the_instrument_are_an_error_at_its_line(
    tmp_path: Path,
) -> None:
    errors = _errors(tmp_path, _script("play t.txt tempo 45% transpose 12"))
    assert [(line, col) for line, col, _ in errors] == [(3, 1)]
    message = errors[0][2]
    assert message.startswith("7 notes cannot be played (E6 at 0.50 s, G6 at 0.75 s, C7")
    assert "as written every note fits: leave the transposition out" in message
    (tmp_path / "low.txt").write_text("tempo 60\nC4 q E4 q G4 q\n")
    errors = _errors(tmp_path, _script("play low.txt transpose 1"))
    assert errors[0][2].endswith("transpose by 13 semitones in all (transpose 13)")


def test_a_tempo_is_said_as_the_script_writes_it(tmp_path: Path) -> None:
    for written, shown in (("0.45", "0.45%"), ("450%", "450%"), ("0.1%", "0.1%")):
        errors = _errors(tmp_path, _script(f"play t.txt tempo {written}"))
        assert [(line, col) for line, col, _ in errors] == [(3, 18)]
        assert errors[0][2] == (
            f"tempo must be a factor 0.1..4 (10%..400%) of the written speed, got {shown}"
        )


@pytest.mark.filterwarnings("ignore::armkit.drawing.DrawingWarning")
@pytest.mark.parametrize("svg", ["empty.svg", "text.svg"])
def test_a_drawing_with_nothing_to_draw_is_an_error_at_its_line_as_draw_svg_says(
    tmp_path: Path,
    svg: str,
    monkeypatch: pytest.MonkeyPatch,
    capsys: pytest.CaptureFixture[str],
) -> None:
    errors = _errors(tmp_path, _script(f"draw {svg} on A5", scene="drawing"))
    assert errors == [(3, 1, f"{tmp_path / svg}: nothing to draw")]
    monkeypatch.chdir(tmp_path)
    assert main(["--scene", "drawing", "draw", "svg", str(tmp_path / svg), "--dry-run"]) == 2
    assert capsys.readouterr().err.endswith(f"armkit: error: {tmp_path / svg}: nothing to draw\n")


def test_run_refuses_a_drawing_with_nothing_to_draw_before_the_first_move(tmp_path: Path) -> None:
    (tmp_path / "empty.svg").write_text(EMPTY_SVG)
    world = World()
    with Arm("openmanipulator_x", "sim", world=world, scene=load_scene("drawing")) as arm:
        before, start = world.arm().q().copy(), world.now()
        with pytest.raises(ScriptCheckError, match="nothing to draw"):
            script = _script("draw empty.svg on A5", scene="drawing")
            run_source(arm, Source("job.arm", script), base_dir=tmp_path)
        assert np.array_equal(world.arm().q(), before) and world.now() == start


def test_good_plays_and_draws_still_check(tmp_path: Path) -> None:
    assert _errors(tmp_path, _script("play t.txt tempo 46%")) == []
    shipped = Path(__file__).parents[2] / "examples" / "scripts" / "square.svg"
    (tmp_path / "square.svg").write_text(shipped.read_text())
    assert _errors(tmp_path, _script("draw square.svg on A5", scene="drawing")) == []
