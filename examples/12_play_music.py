"""Plan three shipped tunes on the shipped glockenspiel and snare (scene
xylophone.toml) for the OpenManipulator-X holding the scene's mallet, refuse
what it cannot play in time, and write what the plan would sound like as a WAV.

Each strike is scheduled backwards from its note: the Dynamixel servos' own
time-based profile says how long the stroke from the hover pose takes to reach
the bar, so the stroke starts that long before the note. A tune too fast for
the arm is refused with every late note listed, and a slower tempo suggested.
(Only the plan here, no arm: the WAV is of the planned contacts;
examples/26_play_xylophone.py plays on the simulated arm and writes the
contacts it really made.)

Needs: the midi extra (pip install 'armkit[midi]'; ``make test`` has it).
Run: .venv/bin/python examples/12_play_music.py
"""

from __future__ import annotations

from pathlib import Path

from armkit.model import load_model
from armkit.music import (
    PerformanceError,
    check_performance,
    load_score,
    plan_performance,
    render,
    time_based_predictor,
    timed_predictor,
    write_wav,
)
from armkit.scene import load_scene

TUNES = Path(__file__).parent / "music"


def main() -> None:
    scene = load_scene("xylophone")  # a C5-C6 glockenspiel, a snare and a mallet
    model = load_model("openmanipulator_x")
    mallet = next(p.tip_offset for p in scene.pens if p.name == "mallet")
    arm = model.with_tool_length(model.tool_length + mallet)  # the mallet's tip is the tool
    predictor = time_based_predictor(arm)
    for name in ("ode_to_joy.mid", "twinkle.rtttl", "frere_jacques.txt"):
        score = load_score(TUNES / name)
        tempo = 1.0
        for _ in range(6):
            perf = plan_performance(
                score, scene.instruments, arm, predictor,
                T_world_base=scene.T_world_base, tempo=tempo,
                rebound=timed_predictor(arm),  # the XM430s' timed rebound
            )  # fmt: skip
            try:
                check_performance(perf)
                break
            except PerformanceError as err:
                print(
                    f"{name} at tempo x{tempo:.2f}: refused, {len(err.problems)} problems,"
                    f" e.g. {err.problems[0]}"
                )
                tempo = perf.suggested_tempo or tempo * 0.9
        speeds = [s.speed for s in perf.strikes]
        print(
            f"{name}: {len(perf.strikes)} strikes in {perf.strikes[-1].time:.1f} s at tempo"
            f" x{tempo:.2f}, {len(perf.moves)} servo commands, contact speed"
            f" {min(speeds):.2f}..{max(speeds):.2f} m/s, hover"
            f" {min(s.hover for s in perf.strikes) * 1000:.0f}..{max(s.hover for s in perf.strikes) * 1000:.0f} mm"
        )
        wav = write_wav(Path(name).with_suffix(".wav").name, render(perf.contacts()))
        print(f"  wrote {wav} ({wav.stat().st_size // 1024} KiB)")


if __name__ == "__main__":
    main()
