"""Seed 001's board task on the OpenManipulator-X: turn the three cubes in
their holders, then stack them on the green one, each one cube (25 mm) higher.

The whole task -- 106 steps, every inverse kinematics and every clearance
check of every move -- is planned before the first motion. Then it runs on the
simulated arm: the task attaches the scene's physics to the arm's world, so the
cubes are grasped, carried and put down, and the run is checked against the
plan (every cube within 1 mm of where the plan puts it, or ``TaskFailed``
naming the step).

Run: .venv/bin/python examples/24_board_task.py
"""

from __future__ import annotations

from armkit import Arm, tasks
from armkit.scene import load_scene

scene = load_scene("board_001")
with Arm("openmanipulator_x", "sim") as arm:
    print(tasks.stack(arm, scene, ["green", "red", "blue"], dry_run=True).lines()[0])
    plan = tasks.stack(arm, scene, ["green", "red", "blue"])  # planned again, then run
    physics = tasks.attached(arm)
    assert physics is not None
    for event in physics.events:
        print(f"{event.t:6.2f} s  {event.detail}")
    for name in ("green", "red", "blue"):
        x, y, z = (round(float(v) * 1000, 1) for v in physics.cube(name).position)
        print(f"{name} now at ({x}, {y}, {z}) mm")
