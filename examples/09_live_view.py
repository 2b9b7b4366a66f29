"""Watch the simulated OpenManipulator-X in a live 3D page while this program moves it.

The view (viser, ``pip install 'armkit[web]'``) serves a page on this computer
only; open the printed URL in a browser. The simulation runs in real time
(``World(realtime=True)``), 001's board scene is on the table, and its physics
(``ScenePhysics``) grasps and carries the cubes: the view shows the World's
truth (``WorldSource``), so the red cube leaves its socket in the gripper. A
target marker says whether a point is reachable, on a cube and clear.
Pass --forever to keep the page open (Ctrl-C stops).

Needs: the web extra (pip install 'armkit[web]'; ``make test`` has it).
Run: .venv/bin/python examples/09_live_view.py
"""

from __future__ import annotations

import math
import sys
import time

import armkit
from armkit import tasks
from armkit.scene import ScenePhysics, load_scene
from armkit.sim import World
from armkit.viz import WorldSource
from armkit.viz.web import View

scene = load_scene("board_001")
world = World(realtime=True)
with armkit.Arm("openmanipulator_x", world=world, scene=scene) as arm:
    physics = ScenePhysics(scene)
    world.attach(physics)
    with View(WorldSource(world, physics=physics), scene=scene, port=0) as view:
        view.start()
        print(f"live view: {view.url}")
        for xyz, pitch in (((0.22, -0.045, 0.0155), -90.0), ((0.45, 0.0, 0.05), -90.0)):
            check = view.set_target(xyz, math.radians(pitch))
            verdict = "reachable" if check.ok else check.reason
            on = f" on {check.on}" if check.on else ""
            print(f"target {tuple(round(v * 1000) for v in xyz)} mm{on}: {verdict}")
        start = time.monotonic()
        tasks.run_plan(arm, tasks.pick(arm, scene, "red", dry_run=True))
        seconds = time.monotonic() - start
        red = physics.cube("red").position * 1000
        print(f"picked red in {seconds:.1f} s of real time; it is now at z {red[2]:.0f} mm")
        print(f"the page got {view.stats().updates} updates")
        while "--forever" in sys.argv:
            time.sleep(1.0)
world.close()
