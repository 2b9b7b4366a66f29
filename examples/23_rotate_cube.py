"""Seed 001's cube rotation: pick the cube from the side (pitch 0) and put it
down in the same place from the top (pitch -90): it turns a quarter turn,
its top face then facing away from the arm ("forward"); "backward" is the
other way round. The side grasp is shifted up so the wrist clears the holders.

Run: .venv/bin/python examples/23_rotate_cube.py
"""

from __future__ import annotations

from armkit import Arm, tasks
from armkit.scene import load_scene

scene = load_scene("board_001")
with Arm("openmanipulator_x", "sim") as arm:
    for direction in ("forward", "backward"):
        plan = tasks.rotate_cube(arm, scene, "green", direction, dry_run=True)
        grasps = [s for s in plan.steps if s.label.endswith("down 3/3")]
        for step in grasps:
            x, y, z = (round(v * 1000, 1) for v in step.point)
            print(f"{direction:8s} {step.label:55s} at ({x}, {y}, {z}) mm")
        print(f"{direction:8s} {plan.lines()[-1].strip()}")
    tasks.run_plan(arm, tasks.rotate_cube(arm, scene, "green", "forward", dry_run=True))
    print("done; the arm is at", arm.position())
