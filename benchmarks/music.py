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

A second table: the shortest interval between two strikes the planner plays, between
adjacent bars (C5 D5 C5 D5 ...), across the row (C5 C6 ...) and on one bar (E5 E5 ...),
found by bisection on the tempo, beside the servos' physical minimum: the time the
joints need, at their servos' own speed and acceleration limits (``servo_speed_dps``,
``servo_accel_dps2``; bang-bang, each joint alone), to go from one contact up to the
next bar's lowest hover and down to its contact. Issue 28's targets: 0.25 s between
adjacent bars and 0.17 s on one bar on the OpenManipulator-X, within 1.5x on the Lynx6.

Run: .venv/bin/python benchmarks/music.py
"""

from __future__ import annotations

import os
import time
from pathlib import Path

import numpy as np

from armkit import Arm
from armkit.model import load_model
from armkit.music import LatencyTable, PerformanceError, Played, Score, plan_play, play
from armkit.music._play import mallet_model
from armkit.music._score import Note
from armkit.music._strike import strike_poses
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


PAIRS = {"adjacent bars": (72, 74), "across the row": (72, 84), "one bar": (76, 76)}


def shortest_interval(arm_name: str, a: int, b: int) -> float:
    """The least time [s] between strikes the planner plays alternating ``a`` and ``b``."""
    model = load_model(arm_name)
    lo, hi = 0.01, 2.0  # [s] plays at hi, not at lo
    for _ in range(14):
        mid = (lo + hi) / 2
        notes = tuple(Note(k * mid, (a, b)[k % 2], 80, mid) for k in range(8))
        try:
            plan_play(model, SCENE, Score(notes, f"{a}-{b}"))
            hi = mid
        except PerformanceError:
            lo = mid
    return hi


def physical_minimum(arm_name: str, a: int, b: int) -> float:
    """A lower bound [s] on the time from a contact on ``a`` to one on ``b`` passing ``b``'s
    10 mm hover, at the servos' own limits: each joint alone, free to be moving at either
    contact; a joint that turns back at the hover stops there (``_leg``), one that does
    not runs at its full speed."""
    model = mallet_model(load_model(arm_name), SCENE)
    bars = SCENE.instruments[0]
    v = np.array([j.peak_velocity for j in model.joints])
    acc = np.array([j.peak_acceleration for j in model.joints])
    pa = strike_poses(model, SCENE.to_base(bars.bar_top(a)), 0.01, 0.0, -np.pi / 3, model.home)
    pb = strike_poses(model, SCENE.to_base(bars.bar_top(b)), 0.01, 0.0, -np.pi / 3, pa.through)
    up, down = pb.hover - pa.through, pb.through - pb.hover
    turns = up * down < 0.0
    times = np.where(
        turns, _leg(np.abs(up), v, acc) + _leg(np.abs(down), v, acc), np.abs(up + down) / v
    )
    return float(np.max(times))


def _leg(d: np.ndarray, v: np.ndarray, a: np.ndarray) -> np.ndarray:
    """Least time [s] to cover ``d`` [rad] ending (or starting) at rest, speed <= ``v``."""
    short = d <= v * v / (2 * a)
    return np.where(short, np.sqrt(2 * d / a), (d - v * v / (2 * a)) / v + v / a)


def intervals() -> None:
    print(f"\n{'arm':18s} {'strikes':15s} {'planned s':>9s} {'physical s':>10s} {'target s':>8s}")
    for arm_name in ARMS:
        scale = 1.0 if arm_name == "openmanipulator_x" else 1.5
        for what, (a, b) in PAIRS.items():
            target = (0.17 if a == b else 0.25) * scale if what != "across the row" else None
            shown = f"{target:8.3f}" if target else f"{'-':>8s}"
            print(
                f"{arm_name:18s} {what:15s} {shortest_interval(arm_name, a, b):9.3f} "
                f"{physical_minimum(arm_name, a, b):10.3f} {shown}",
                flush=True,
            )


def main() -> None:
    print(f"load average {' '.join(f'{v:.2f}' for v in os.getloadavg())} ({os.cpu_count()} cores)")
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
    intervals()


if __name__ == "__main__":
    main()
