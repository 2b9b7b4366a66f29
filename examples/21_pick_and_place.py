"""Pick a cube up and put it down somewhere else, planned whole before anything moves.

The scene (seed 001's board) says where the cubes are; ``tasks.pick`` comes
down onto green from 30 mm above in three waypoints (from the top, where the
OpenManipulator-X reaches), closes and goes back up; ``tasks.place`` then puts
it in the free socket board[2, 2], nearer the arm, with the same face up. Each call returns its plan; here the plans are printed, then carried
out by the simulated arm (objects follow in the simulator's world when it has
one; this script only moves the arm).

Run: .venv/bin/python examples/21_pick_and_place.py
"""

from __future__ import annotations

from armkit import Arm, tasks
from armkit.scene import load_scene

scene = load_scene("board_001")
with Arm("openmanipulator_x", "sim") as arm:
    pick = tasks.pick(arm, scene, "green", dry_run=True)
    print(pick)
    tasks.run_plan(arm, pick)
    place = tasks.place(arm, scene, "green", "board[2,2]", dry_run=True)
    print(place.lines()[0])
    print(place.lines()[-1])
    tasks.run_plan(arm, place)
    print("the arm is now at", arm.position())
