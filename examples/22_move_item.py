"""Seed 000's moveItem: pick a cube up, lift it before travelling, put it down at B.

A scene can be built in code as well as loaded from a file. The lift is 50 mm;
the whole way is planned and checked (reach, joint limits, the table, the other
objects) before the first motion, so a point out of reach moves nothing.

Run: .venv/bin/python examples/22_move_item.py
"""

from __future__ import annotations

import numpy as np

from armkit import Arm, tasks
from armkit.scene import Cube, Place, Scene
from armkit.tasks import TaskError

scene = Scene(
    "two_places",
    cubes=(Cube("box", 0.025, np.array([0.20, -0.06, 0.0])),),
    places=(Place("B", np.array([0.19, 0.07, 0.0])),),
)
with Arm("openmanipulator_x", "sim") as arm:
    plan = tasks.move_item(arm, scene, "box", "B", lift=50, dry_run=True)
    print(plan)
    tasks.run_plan(arm, plan)
    try:
        tasks.move_item(arm, scene, "box", (450.0, 0.0, 0.0), dry_run=True)
    except TaskError as refused:
        print("refused, nothing moved:", refused)
