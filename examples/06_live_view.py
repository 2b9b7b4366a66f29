"""Watch the simulated OpenManipulator-X in a live 3D page while this program moves it.

The view (viser, ``pip install 'armkit[web]'``) serves a page on this computer
only; open the printed URL in a browser. The arm visits the cubes of a small
test scene at the pace of real time, a target marker says whether a point is
reachable and clear, and the program prints how many updates it sent.
Pass --forever to keep the page open (Ctrl-C stops).

Run: .venv/bin/python examples/06_live_view.py
"""

from __future__ import annotations

import math
import sys
import time

import armkit
from armkit.viz import DriverSource, Goal, Mover, cubes_scene, default_tour
from armkit.viz.web import View

with (
    armkit.Arm("openmanipulator_x") as arm,
    View(DriverSource(arm.model, arm.driver), scene=cubes_scene(), port=0) as view,
):
    view.start()
    print(f"live view: {view.url}")
    for xyz, pitch in (((0.2, -0.08, 0.07), -90.0), ((0.45, 0.0, 0.05), -90.0)):
        check = view.set_target(xyz, math.radians(pitch))
        print(
            f"target {tuple(round(v * 1000) for v in xyz)} mm: {'reachable' if check.ok else check.reason}"
        )
    mover = Mover(arm)
    start = time.monotonic()
    for q in default_tour(arm.model):
        mover.request(Goal(q=q, speed=1.0))
        mover.wait_idle()
    mover.close()
    seconds = time.monotonic() - start
    stats = view.stats()
    print(f"the arm visited the cubes in {seconds:.1f} s; the page got {stats.updates} updates")
    x, y, z, p = arm.position()
    print(f"back home: gripper at ({x:.0f}, {y:.0f}, {z:.0f}) mm, pitch {p:.0f} deg")
    while "--forever" in sys.argv:
        time.sleep(1.0)
