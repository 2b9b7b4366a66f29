"""Child process for the exit-path tests: a simulated OWI on the real clock,
every command appended to a log file; one long move, then whatever the test does."""

from __future__ import annotations

import math
import sys
from pathlib import Path

from armkit.devices.owi535 import open_device
from armkit.drivers.timed import TimedDriver, WallClock, state_path
from armkit.model import load_model
from armkit.sim.owi_sim import build_sim


class ExplodingClock(WallClock):
    """The real clock, except that a sleep longer than 0.2 s fails half way."""

    def sleep(self, seconds: float) -> None:
        if seconds > 0.2:
            super().sleep(0.2)
            raise RuntimeError("simulated program error in the middle of a move")
        super().sleep(seconds)


def main(mode: str, log: str) -> None:
    model = load_model("owi535")
    clock = ExplodingClock() if mode == "exception" else WallClock()
    sim = build_sim(model, 3, clock=clock, log_path=Path(log))
    driver = TimedDriver(model, open_device(sim.backend), clock, state_path("child"), "child")
    driver.set_light(True)
    if mode == "exit":
        driver.turn_for("base", 1, 0.25)
        sys.exit(0)  # no close(): atexit must stop the arm
    driver.turn_to("base", math.radians(130))  # ~8 s: long enough to be interrupted


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
