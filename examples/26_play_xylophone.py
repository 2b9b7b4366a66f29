"""Play a short tune on the xylophone with the simulated OpenManipulator-X and
write what it really played as a WAV file.

The arm holds a mallet (the scene's ``mallet``: the tool 20 mm longer). The
whole tune is planned first, every strike scheduled backwards from its note
with the XM430s' own time-based profiles, and checked (reach, clearance, time
between notes); then the commands go out at their times on the simulated
servos while a Listener on the World hears every contact of the mallet with a
bar. The WAV is made from those contacts, so it sounds as the arm played.
Before the tune, a calibration pass strikes every bar once and measures each
bar's onset delay: the per-bar latency table (written beside the WAV as TOML,
delays in ms; ``armkit play --calibrate OUT.toml`` / ``--latency FILE.toml``)
that the tune is then planned with.

Run: .venv/bin/python examples/26_play_xylophone.py [OUT.wav]
"""

from __future__ import annotations

import sys
from pathlib import Path

from armkit import Arm
from armkit.music import (
    PerformanceError,
    calibrate,
    parse_notelist,
    play,
    render,
    save_latency,
    write_wav,
)
from armkit.scene import load_scene
from armkit.sim import World

TUNE = """tempo 80 mf
C5 q  E5 q  G5 q  E5 q
C5 e  D5 e  E5 e  F5 e  f G5 h
snare h  ff C5 q
"""


def main(out: Path) -> None:
    scene = load_scene("xylophone")
    tune = out.with_suffix(".txt")
    tune.write_text(TUNE, encoding="utf-8")
    print(f"{len(parse_notelist(TUNE, str(tune)).notes)} notes in {tune}")
    with Arm("openmanipulator_x", "sim", world=World(), scene=scene) as arm:
        table = calibrate(arm, scene)  # one strike per bar, heard in the simulator
        delays = [d * 1000 for _, d in table.delays]
        path = save_latency(table, out.with_suffix(".latency.toml"))
        print(f"calibrated {len(delays)} bars: {min(delays):.2f}..{max(delays):.2f} ms -> {path}")
        try:
            played = play(arm, scene, tune, tempo=0.8, latency=table)
        except PerformanceError as err:  # too fast: every late note and a tempo that fits
            raise SystemExit(f"refused: {err}") from None
    stats = played.stats
    assert stats is not None  # the simulator listened
    for planned, heard in zip(played.performance.strikes, played.contacts, strict=False):
        late = (heard.time - planned.time) * 1000
        print(
            f"  {planned.target.note.name:6s} planned {planned.time:6.3f} s  heard "
            f"{heard.time:6.3f} s ({late:+5.2f} ms)  {heard.speed:.2f} m/s"
        )
    print(
        f"onset error RMS {stats.rms * 1000:.2f} ms, max {stats.max * 1000:.2f} ms, "
        f"{len(stats.missed)} missed, {len(stats.extra)} extra; longest on a bar "
        f"{max(played.dwell) * 1000:.1f} ms"
    )
    print(f"wrote {write_wav(out, render(played.contacts))}")


if __name__ == "__main__":
    main(Path(sys.argv[1] if len(sys.argv) > 1 else "xylophone.wav"))
