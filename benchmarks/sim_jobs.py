"""How fast the simulator runs while a job streams to it (issue 29 item 6): simulated
seconds per CPU second of the whole process (driver, protocol, simulated devices,
world, observers), for the OpenManipulator-X drawing examples/drawings/curve.svg on
the drawing scene (target >= 50x) and the 001 board task (target >= 200x).

An observer notes the process's CPU time at every simulated second; the table gives
the factor over the whole job and over its 1 s windows (median, the slowest 10 % and
the slowest window: where the streaming is densest). CPU time, not wall: on a shared
machine the wall time depends on the neighbours (the load is printed).

Run: .venv/bin/python benchmarks/sim_jobs.py [--quick]   (--quick: the first 60 strokes)
"""

from __future__ import annotations

import contextlib
import os
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from armkit import Arm, tasks
from armkit.drawing import draw
from armkit.scene import load_scene
from armkit.sim import World

CURVE = Path(__file__).resolve().parent.parent / "examples" / "drawings" / "curve.svg"
CUBES = ("red", "green", "blue")


class Pace:
    """Observer: the process's CPU time [s] at every simulated second."""

    def __init__(self) -> None:
        self.marks: list[tuple[float, float]] = []
        self.next = 0.0

    def on_step(self, world: World, t: float) -> None:
        if t >= self.next:
            self.marks.append((t, time.process_time()))
            self.next = t + 1.0

    def on_steps(self, world: World, times: np.ndarray) -> None:
        self.on_step(world, float(times[-1]))  # a stretch stepped at once: its end

    def may_skip(self) -> bool:
        return True  # never keeps the world stepping

    def table_row(self, label: str, target: float) -> str:
        t, cpu = np.array(self.marks).T
        windows = np.diff(t) / np.maximum(np.diff(cpu), 1e-9)
        whole = (t[-1] - t[0]) / (cpu[-1] - cpu[0])
        p10 = np.percentile(windows, 10)
        return (
            f"{label:<24} {t[-1] - t[0]:8.1f} {cpu[-1] - cpu[0]:7.1f} {whole:7.1f} "
            f"{np.median(windows):7.1f} {p10:7.1f} {windows.min():7.1f} {target:7.0f}"
        )


def drawing(quick: bool) -> Pace:
    """The OpenManipulator-X drawing curve.svg (``quick``: its first 60 strokes)."""
    world, pace = World(), Pace()
    with Arm("openmanipulator_x", "sim", world=world) as arm:
        world.attach(pace)
        scene = load_scene("drawing")
        stop = _StopAfter(60) if quick else None
        with contextlib.suppress(_Enough):  # --quick: stopped after its strokes
            draw(arm, scene, CURVE, progress=stop)
    return pace


def board() -> Pace:
    """The 001 board task (rotate, then stack three cubes) on the OpenManipulator-X."""
    world, pace = World(), Pace()
    with Arm("openmanipulator_x", "sim", world=world) as arm:
        world.attach(pace)
        tasks.stack(arm, load_scene("board_001"), CUBES, rotate_first="forward")
    return pace


class _Enough(Exception):
    pass


class _StopAfter:
    """A drawing's progress that stops it after ``n`` strokes."""

    def __init__(self, n: int) -> None:
        self.n = n

    def __call__(self, job: object, done: int) -> None:
        if done >= self.n:
            raise _Enough


def main() -> None:
    quick = "--quick" in sys.argv
    print(f"load average {' '.join(f'{v:.2f}' for v in os.getloadavg())} ({os.cpu_count()} cores)")
    os.environ.setdefault("ARMKIT_CONFIG_DIR", tempfile.mkdtemp(prefix="armkit-bench-"))
    print("simulated seconds per CPU second while a job streams (1 s windows)")
    head = (
        f"{'job':<24} {'sim s':>8} {'cpu s':>7} {'whole':>7} {'median':>7} {'p10':>7} "
        f"{'worst':>7} {'target':>7}"
    )
    print(head + "\n" + "-" * len(head))
    label = "curve.svg" + (" (60 strokes)" if quick else "")
    print(drawing(quick).table_row(label, 50.0))
    print(board().table_row("001 board task", 200.0))


if __name__ == "__main__":
    main()
