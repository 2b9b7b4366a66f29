"""Strikes on the beat: the shipped tunes played in the simulator, contacts heard.

For the OpenManipulator-X (its Dynamixel driver on simulated XM430s) and the
Lynx6 (its SSC-32 driver on a simulated SSC-32), each in the shipped
``xylophone`` scene, three tunes: ``ode_to_joy.mid`` (a shipped MIDI file with a
tempo change), ``twinkle.rtttl`` (RTTTL) and ``frere_jacques.txt`` (a note list
with tempo changes), each at two tempi: the fastest the planner accepts
(starting from the written tempo, then its suggestion) and 80 % of that.
``armkit.music.play`` plans and plays; a Listener on the World hears each
contact. Reported: notes refused at the written tempo, onset error RMS and max
against the score [ms] (targets: RMS <= 2 ms, max <= 5 ms), missed and extra
notes, the longest time the mallet stayed below a bar top [ms] (the rebound),
and the same errors after one calibration run (``LatencyTable.from_run``).

Run: .venv/bin/python benchmarks/music.py
"""

from __future__ import annotations

import time
from pathlib import Path

from armkit import Arm
from armkit.music import LatencyTable, PerformanceError, Played, play
from armkit.scene import load_scene
from armkit.sim import World

TUNES = Path(__file__).parents[1] / "examples" / "music"
NAMES = ("ode_to_joy.mid", "twinkle.rtttl", "frere_jacques.txt")
ARMS = ("openmanipulator_x", "lynx6")
SCENE = load_scene("xylophone")


def _play(arm_name: str, tune: Path, tempo: float, latency: LatencyTable | None = None) -> Played:
    with Arm(arm_name, "sim", world=World(), scene=SCENE) as arm:
        return play(arm, SCENE, tune, tempo=tempo, latency=latency)


def fastest(arm_name: str, tune: Path) -> tuple[float, int]:
    """The fastest accepted tempo factor (two decimals), and the notes refused at 1."""
    refused, tempo = 0, 1.0
    with Arm(arm_name, "sim", world=World(), scene=SCENE) as arm:
        for _ in range(20):
            try:
                play(arm, SCENE, tune, tempo=tempo, dry_run=True)
                return tempo, refused
            except PerformanceError as err:
                count = len({id(p.note) for p in err.problems})
                refused = refused or count
                tempo = round(tempo - 0.01, 2)
    raise SystemExit(f"{arm_name}: {tune.name} cannot be played even at {tempo}")


def row(arm_name: str, tune: Path, tempo: float, refused: int) -> str:
    t0 = time.perf_counter()
    first = _play(arm_name, tune, tempo)
    wall = time.perf_counter() - t0
    s = first.stats
    assert s is not None
    table = LatencyTable.from_run(first.performance.contacts(), first.contacts, first.latency)
    again = _play(arm_name, tune, tempo, table).stats
    assert again is not None
    return (
        f"{arm_name:18s} {tune.name:18s} {tempo:5.2f} {len(first.performance.strikes):5d} "
        f"{refused:7d} {s.rms * 1e3:6.2f} {s.max * 1e3:6.2f} {len(s.missed):6d} "
        f"{len(s.extra):5d} {max(first.dwell, default=0.0) * 1e3:9.1f} "
        f"{again.rms * 1e3:7.2f} {again.max * 1e3:7.2f} {wall:6.1f}"
    )


def main() -> None:
    print(
        f"{'arm':18s} {'tune':18s} {'tempo':>5s} {'notes':>5s} {'refused':>7s} "
        f"{'rms ms':>6s} {'max ms':>6s} {'missed':>6s} {'extra':>5s} {'on bar ms':>9s} "
        f"{'cal rms':>7s} {'cal max':>7s} {'wall s':>6s}"
    )
    for arm_name in ARMS:
        for name in NAMES:
            tune = TUNES / name
            tempo, refused = fastest(arm_name, tune)
            for factor in (tempo, round(0.8 * tempo, 2)):
                print(row(arm_name, tune, factor, refused), flush=True)
    print(
        "tempo: factor of the written tempo; refused: notes the planner refuses at the "
        "written tempo; on bar: longest time the mallet stayed below a bar top (ms); cal: after "
        "one calibration run (per-bar latency table)"
    )


if __name__ == "__main__":
    main()
