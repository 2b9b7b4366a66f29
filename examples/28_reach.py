"""Seed 003's reach: find a hand held out in front of the arm with the distance
sensor (the scan at the hand's height), come towards it along the beam until
the sensor reads 60 mm, shake it three times, go home.

Run: .venv/bin/python examples/28_reach.py
"""

from __future__ import annotations

from armkit import Arm, tasks
from armkit.scene import load_scene

scene = load_scene("reach_003")
with Arm("lynx6", "sim") as arm:
    result = tasks.reach(arm, scene, height=110.0, near=60.0, shakes=3)  # mm
    print("\n".join(result.lines()))
