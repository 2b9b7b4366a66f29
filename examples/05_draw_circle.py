"""Draw a 40 mm circle with the simulated OpenManipulator-X and measure how well it went.

``driver="sim"`` runs the arm's real Dynamixel driver on simulated XM430 servos
that lag behind their profiles like real ones; the simulation world records the
true joint angles every millisecond of simulated time (``arm.world``). Forward
kinematics turns that record into the pen's true path, which we compare with
the ideal circle for the three ways of sending waypoints (seed 001).

Run: .venv/bin/python examples/05_draw_circle.py
"""

from __future__ import annotations

import numpy as np

from armkit.arm import Arm
from armkit.kinematics import fk
from armkit.model import load_model
from armkit.motion import (
    EarlyStreaming,
    NaiveStepping,
    TimedStreaming,
    circle,
    distance_to_polyline,
)

CENTER_MM = (170.0, 0.0, 50.0)
RADIUS_MM = 40.0
PEN_DOWN_DEG = -90.0  # pitch: the pen points straight down

for name, streamer in [
    ("naive stepping", NaiveStepping()),
    ("early waypoints (at 50 %)", EarlyStreaming(fraction=0.5)),
    ("timed streaming (100 Hz, 60 mm/s)", TimedStreaming(rate=100.0, speed=0.06)),
]:
    model = load_model("openmanipulator_x")
    with Arm(model, driver="sim") as arm:
        world = arm.world  # where the simulated arm's truth lives
        assert world is not None
        points = circle(np.array(CENTER_MM) / 1000, RADIUS_MM / 1000, spacing=0.002) * 1000
        arm.move_to(*points[0], PEN_DOWN_DEG)
        start = arm.clock.now()
        arm.follow(points, PEN_DOWN_DEG, streamer=streamer)
        took = arm.clock.now() - start
        record = world.recording().between(start, arm.clock.now())
        pen = fk(arm.model, record.q)[:, :3, 3] * 1000
        error = distance_to_polyline(pen, points)
        print(
            f"{name:<36} {len(points)} waypoints, {took:5.2f} s simulated, "
            f"path error rms {np.sqrt(np.mean(error**2)):.3f} mm, max {error.max():.3f} mm"
        )
        x, y, z, pitch = arm.position()
        print(f"{'':<36} pen now at ({x:.1f}, {y:.1f}, {z:.1f}) mm, pitch {pitch:.1f} deg")
