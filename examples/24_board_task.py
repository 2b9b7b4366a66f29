"""Seed 001's board task on the OpenManipulator-X: turn the three cubes in
their holders, then stack them on the green one, each one cube (25 mm) higher.

The whole task -- 106 steps, every inverse kinematics and every clearance
check of every move -- is planned before the first motion; the plan prints
each step and where each cube is expected to end.

Run: .venv/bin/python examples/24_board_task.py
"""

from __future__ import annotations

from armkit import Arm, tasks
from armkit.scene import load_scene

scene = load_scene("board_001")
with Arm("openmanipulator_x", "sim") as arm:
    plan = tasks.stack(arm, scene, ["green", "red", "blue"], dry_run=True)
    print(plan)
    tasks.run_plan(arm, plan)
    print("done; the arm is at", arm.position())
