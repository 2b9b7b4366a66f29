"""Drawing accuracy and time on the simulated servo arms.

A 50 mm-radius circle and a 100 mm square, drawn by the simulated
OpenManipulator-X and Lynx6 (each arm's own driver on its simulated device:
XM430 servos on a Dynamixel bus, an SSC-32) with naive stepping, early-waypoint
streaming (seed 001) and time-parametrised streaming. For each: RMS and maximum
distance of the true gripper path (1 kHz of the world's true joint angles
through FK) from the ideal path [mm], and the simulated drawing time [s].

"floor" is what the device's resolution alone costs: the ideal path's joint
angles rounded to what the controller can be told (an XM430's tick, 0.088 deg;
an SSC-32's whole microsecond, about 0.09 deg), RMS distance from the path [mm].
A drawing cannot be expected below it (the servos' lag smooths the steps, so a
streamed drawing may come out a little under it).

Run: .venv/bin/python benchmarks/paths.py
"""

from __future__ import annotations

import math
import os
import time
from collections.abc import Callable

import numpy as np
from numpy.typing import NDArray

from armkit.connect import open_driver, world_of
from armkit.drivers.dynamixel import DynamixelDriver
from armkit.drivers.servo import ServoArmDriver
from armkit.kinematics import fk
from armkit.model import ArmModel, load_model
from armkit.motion import (
    EarlyStreaming,
    NaiveStepping,
    Streamer,
    TimedStreaming,
    circle,
    distance_to_polyline,
    plan_path,
    rectangle,
)

F64 = NDArray[np.float64]
SPACING = 0.002  # [m] between waypoints
# arm -> (centre of the drawing [m], pitch [rad])
SETUPS = {
    "openmanipulator_x": ((0.17, 0.0, 0.05), -math.pi / 2),
    "lynx6": ((0.17, 0.0, 0.03), -math.pi / 3),
}
SHAPES: dict[str, Callable[[tuple[float, float, float], float], F64]] = {
    "circle r50": lambda c, sp: circle(c, 0.05, sp),
    "square 100": lambda c, sp: rectangle(c, 0.1, 0.1, sp),
}
MODES: dict[str, Streamer] = {
    "naive": NaiveStepping(),
    "early 0.5": EarlyStreaming(fraction=0.5),
    "timed 100Hz": TimedStreaming(rate=100.0, speed=0.06, accel=0.5),
}


def draw(model: ArmModel, points: F64, pitch: float, streamer: Streamer) -> tuple[F64, float]:
    """Draw ``points`` on a fresh simulated arm; true tool points [m] while drawing, time [s]."""
    arm = open_driver(model, "sim")
    world = world_of(arm)
    assert world is not None
    path = plan_path(model, points, pitch, arm.read())
    arm.move(path.q[0], wait=True)
    world.clock.sleep(0.2)  # pen down: let the servos settle on the first point
    t0 = world.now()
    streamer.run(arm, model, path, world.clock)
    t1 = world.now()
    rec = world.recording().between(t0, t1)
    arm.close()
    return fk(model, rec.q)[:, :3, 3], t1 - t0


def floor(model: ArmModel, ideal: F64, pitch: float) -> float:
    """RMS distance [mm] of the ideal path rounded to the device's resolution."""
    driver = open_driver(model, "sim")
    path = plan_path(model, ideal, pitch, driver.read())
    if isinstance(driver, DynamixelDriver):
        held = np.array([driver.to_angles(driver.to_ticks(q)) for q in path.q])
    else:
        assert isinstance(driver, ServoArmDriver)
        tables = driver.joints
        held = np.array(
            [
                [t.to_value(round(t.to_pulse(a))) for t, a in zip(tables, q, strict=True)]
                for q in path.q
            ]
        )
    driver.close()
    err = distance_to_polyline(fk(model, held)[:, :3, 3], ideal) * 1000
    return float(np.sqrt(np.mean(err**2)))


def main() -> None:
    print(f"load average {' '.join(f'{v:.2f}' for v in os.getloadavg())} ({os.cpu_count()} cores)")
    cols = ("rms mm", "max mm", "time s", "x naive", "floor")
    head = f"{'arm':<18} {'shape':<11} {'mode':<12} " + " ".join(f"{c:>7}" for c in cols)
    print(head)
    print("-" * len(head))
    started = time.perf_counter()
    for arm_name, (centre, pitch) in SETUPS.items():
        model = load_model(arm_name)
        for shape, make in SHAPES.items():
            ideal = make(centre, 0.0002)
            lowest = floor(model, ideal, pitch)
            naive_time = math.nan
            for mode, streamer in MODES.items():
                true, took = draw(model, make(centre, SPACING), pitch, streamer)
                err = distance_to_polyline(true, ideal) * 1000
                naive_time = took if mode == "naive" else naive_time
                rms = float(np.sqrt(np.mean(err**2)))
                print(
                    f"{arm_name:<18} {shape:<11} {mode:<12} {rms:7.3f} {err.max():7.3f} "
                    f"{took:7.2f} {naive_time / took:7.2f} {lowest:7.3f}"
                )
    print(f"\n(simulated; {time.perf_counter() - started:.1f} s of real time for the whole table)")


if __name__ == "__main__":
    main()
