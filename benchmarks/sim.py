"""How fast the simulator runs, and how closely its real-time mode keeps to the wall clock.

1. Speed: for every shipped arm (its own driver on its simulated device, the
   world stepped at 1 kHz), simulated seconds per real second while the arm
   stands idle and while it draws a 30 mm circle (timed streaming at 100 Hz;
   the OWI-535, which cannot stream, steps round 8 points of it).
2. Real time: a ``World(realtime=True)`` with the OpenManipulator-X, idle and
   while it draws; an observer notes, at every step, how far the step ran behind
   the wall clock [ms]: median, 99th percentile and worst (targets: median <= 1 ms,
   p99 <= 5 ms). On a shared 2-core machine the tail depends on the neighbours.
3. While a job streams: ``benchmarks/sim_jobs.py``, simulated seconds per CPU second
   of the OpenManipulator-X drawing examples/drawings/curve.svg (target >= 50x) and of
   the 001 board task (target >= 200x): whole job, median, slowest 10 % and worst 1 s.
4. Replies: ``benchmarks/sim_replies.py``, ``armkit emulate`` answering the official
   dynamixel-sdk beside a CPU load of 2x the cores (median and 99.9th percentile).

Run: .venv/bin/python benchmarks/sim.py
"""

from __future__ import annotations

import math
import os
import tempfile
import time

import numpy as np
import sim_jobs
import sim_replies
from numpy.typing import NDArray

from armkit.connect import open_driver, world_of
from armkit.drivers import Driver
from armkit.kinematics import fk, pitch_of
from armkit.model import ArmModel, load_model, shipped_models
from armkit.motion import NaiveStepping, Streamer, TimedStreaming, circle, plan_path
from armkit.sim import World

F64 = NDArray[np.float64]
IDLE_S = 20.0  # simulated seconds of idling
POSES_DEG = {"puma560": (0.0, 45.0, -135.0, 0.0, 45.0, 0.0)}  # a pose that draws well


def drawing(model: ArmModel, driver: Driver) -> tuple[F64, float | None, Streamer]:
    """A 30 mm horizontal circle about a pose in the middle of the arm's range."""
    middle = 0.5 if model.dof > 2 else 0.6  # a planar arm's middle is its full stretch
    q = np.radians(
        POSES_DEG.get(model.name, np.degrees(model.lower + middle * (model.upper - model.lower)))
    )
    driver.move(q)
    pose = fk(model, q)
    pitch = float(pitch_of(pose)) if 2 < model.dof < 6 else None  # free where it cannot choose
    if model.name == "owi535":
        centre = np.array([0.20, 0.0, 0.20])
        return circle(centre, 0.03, 0.03 * math.pi / 4), 0.0, NaiveStepping()
    points = circle(pose[:3, 3], 0.03, 0.002)
    if model.dof <= 2:  # a planar arm draws in its own (x, z) plane
        turn = np.linspace(0.0, 2.0 * math.pi, 95)
        points = pose[:3, 3] + 0.03 * np.column_stack([np.cos(turn), 0 * turn, np.sin(turn)])
    return points, pitch, TimedStreaming(rate=100.0, speed=0.03)


def speeds(name: str) -> tuple[float, float, float]:
    """(idle, drawing) simulated seconds per real second, and the drawing's simulated time."""
    model = load_model(name)
    driver = open_driver(model, "sim")
    world = world_of(driver)
    assert world is not None
    started = time.perf_counter()
    world.advance(IDLE_S)
    idle = IDLE_S / (time.perf_counter() - started)
    points, pitch, streamer = drawing(model, driver)
    coarse = 0.02 if model.name == "owi535" else 1e-4  # [m] between the OWI's 8 points
    path = plan_path(model, points, pitch, driver.read(), tolerance=coarse)
    driver.move(path.q[0])
    t0, started = world.now(), time.perf_counter()
    streamer.run(driver, model, path, world.clock)
    took = world.now() - t0
    draw = took / (time.perf_counter() - started)
    driver.close()
    return idle, draw, took


class Lag:
    """Observer: how far behind the wall clock each step ran [ms]."""

    def __init__(self, world: World) -> None:
        self.world, self.samples = world, list[float]()
        self.wall0 = time.monotonic()

    def on_step(self, world: World, t: float) -> None:
        self.samples.append(((time.monotonic() - self.wall0) * world.pace - t) * 1000.0)


def realtime_lag(draw: bool, seconds: float = 3.0) -> F64:
    """Step lags [ms] of a real-time world with the OpenManipulator-X, idle or drawing."""
    world = World(realtime=True)
    model = load_model("openmanipulator_x")
    driver = open_driver(model, "sim", world=world)
    lag = Lag(world)
    lag.wall0 = world._wall0  # the world's own origin of wall time
    world.attach(lag)
    if draw:
        points = circle(np.array([0.18, 0.0, 0.08]), 0.03, 0.002)
        path = plan_path(model, points, -math.pi / 2, driver.read())
        driver.move(path.q[0])
        TimedStreaming(rate=100.0, speed=0.06).run(driver, model, path, world.clock)
    else:
        world.clock.sleep(seconds)
    driver.close()
    world.close()
    return np.array(lag.samples[100:])  # after the first 0.1 s


def main() -> None:
    print(f"load average {' '.join(f'{v:.2f}' for v in os.getloadavg())} ({os.cpu_count()} cores)")
    os.environ.setdefault("ARMKIT_CONFIG_DIR", tempfile.mkdtemp(prefix="armkit-bench-"))
    print("simulated seconds per real second, each arm's own driver on its simulated device")
    head = f"{'arm':<18} {'idle':>8} {'drawing':>8} {'drawn s':>8}"
    print(head + "\n" + "-" * len(head))
    for name in shipped_models():
        idle, draw, took = speeds(name)
        print(f"{name:<18} {idle:8.1f} {draw:8.1f} {took:8.2f}")
    print("\nreal-time mode: how far each 1 ms step ran behind the wall clock [ms]")
    head = f"{'openmanipulator_x':<18} {'median':>7} {'p99':>7} {'worst':>7} {'steps':>7}"
    print(head + "\n" + "-" * len(head))
    for label, draw in (("idle", False), ("drawing", True)):
        lags = realtime_lag(draw)
        p50, p99, worst = np.percentile(lags, [50, 99, 100])
        print(f"{label:<18} {p50:7.3f} {p99:7.3f} {worst:7.3f} {len(lags):7d}")
    print("(targets: median <= 1 ms, p99 <= 5 ms)")
    print()
    sim_jobs.main()  # the real-time factor while a job streams
    print()
    sim_replies.main()  # the emulator's reply latency to the dynamixel-sdk under load


if __name__ == "__main__":
    main()
