"""Plan three shipped tunes on a xylophone and a snare for the OpenManipulator-X
holding a stick, refuse what it cannot play in time, and write what the plan
would sound like as a WAV file.

Each strike is scheduled backwards from its note: the Dynamixel servos' own
time-based profile says how long the stroke from the hover pose takes to reach
the bar, so the stroke starts that long before the note. A tune too fast for
the arm is refused with every late note listed, and a slower tempo suggested.
(The instruments here are small stand-ins for the scene's xylophone.toml, and
the WAV is of the planned contacts: examples/26_play_xylophone.py plays on the
simulated arm and writes the contacts it really made.)

Run: .venv/bin/python examples/06_play_music.py
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from armkit.model import load_model
from armkit.music import (
    PerformanceError,
    check_performance,
    load_score,
    plan_performance,
    render,
    time_based_predictor,
    write_wav,
)

TUNES = Path(__file__).parent / "music"
STICK_M = 0.13  # stick tip from the wrist axis: 001's stick gripper and its mallet


@dataclass(frozen=True)
class Xylophone:
    """Two octaves (C5..B6) of bars in a line in front of the arm, tops 20 mm up."""

    name: str = "xylophone"
    notes: range = range(72, 96)

    def bar_top(self, note: int) -> NDArray[np.float64]:
        share = (note - self.notes.start) / (len(self.notes) - 1)
        return np.array([0.16, -0.12 + 0.24 * share, 0.02])


@dataclass(frozen=True)
class Drum:
    """A snare (General MIDI 38) on the arm's left, head 30 mm up."""

    name: str = "snare"
    position: tuple[float, float, float] = (0.10, 0.15, 0.0)
    top_z: float = 0.03
    note: int = 38


def main() -> None:
    arm = load_model("openmanipulator_x").with_tool_length(STICK_M)
    predictor, layout = time_based_predictor(arm), (Xylophone(), Drum())
    for name in ("ode_to_joy.mid", "twinkle.rtttl", "frere_jacques.txt"):
        score = load_score(TUNES / name)
        tempo = 1.0
        for _ in range(6):
            perf = plan_performance(score, layout, arm, predictor, tempo=tempo)
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
