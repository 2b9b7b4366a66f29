"""Pictures of every shipped arm and every shipped scene, as the 3D view shows them.

Each arm stands at its home pose with its joint frames drawn (x red, y green,
z blue: the web view only); each scene is shown with the arm it
was made for and a target marker (green: reachable, on a cube and clear; red:
why not). With --chromium the pictures are the web view's own, rendered by
headless Chromium (Debian's ``chromium``; this is how README's docs/*.png are
made: ``.venv/bin/python examples/10_view_pictures.py --chromium docs``);
without, they are drawn offscreen with Pillow (no browser, no target marker).

Run: .venv/bin/python examples/10_view_pictures.py [--chromium] [FOLDER]
"""

from __future__ import annotations

import math
import sys
import warnings
from pathlib import Path

import numpy as np

import armkit
from armkit.drivers.timed import UncertainEstimateWarning
from armkit.scene import Scene, ScenePhysics, load_scene
from armkit.viz import WorldSource, write_picture

SCENES = {  # scene -> (arm, target [m] in the arm's frame or None, pitch [deg])
    "board_001": ("openmanipulator_x", (0.22, 0.0, 0.0155), -90.0),
    "search_002": ("lynx6", None, -90.0),
    "empty": ("openmanipulator_x", (0.45, 0.0, 0.05), -90.0),
}
args = [a for a in sys.argv[1:] if not a.startswith("--")]
folder = Path(args[0] if args else "view_pictures")
folder.mkdir(exist_ok=True)
browser = "--chromium" in sys.argv
warnings.simplefilter("ignore", UncertainEstimateWarning)  # the OWI: never homed


def picture(name: str, arm_name: str, scene: Scene | None, target: object, pitch: float) -> None:
    with armkit.Arm(arm_name) as arm:
        model = arm.model
        assert arm.world is not None
        physics = ScenePhysics(scene) if scene is not None else None
        source = WorldSource(arm.world, physics=physics)
        path = folder / f"{name}.png"
        if not browser:
            write_picture(model, source.state(), path, scene=scene, title=name)
        else:
            from armkit.viz.web import View, render_png

            with View(source, scene=scene, port=0, frames=scene is None) as view:
                view.update()
                if target is not None:
                    view.set_target(np.array(target), math.radians(pitch))
                render_png(view, path, 1024, 768)
        print(f"wrote {path}")


for arm_name in armkit.model.shipped_models():
    picture(f"view_{arm_name}", arm_name, None, None, 0.0)
for scene_name, (arm_name, target, pitch) in SCENES.items():
    picture(f"scene_{scene_name}", arm_name, load_scene(scene_name), target, pitch)
