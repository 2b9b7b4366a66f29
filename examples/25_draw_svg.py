"""Seed 001's third task on the simulated OpenManipulator-X: pick the pen up from
its stand, draw an SVG on the A5 sheet of the shipped ``drawing`` scene, put the
pen back, and measure what the simulated pen drew.

Needs: the svg extra (pip install 'armkit[svg]'; ``make test`` has it).
"""

from pathlib import Path

from armkit import Arm
from armkit.drawing import draw
from armkit.scene import load_scene
from armkit.sim import World

HERE = Path(__file__).parent
scene = load_scene("drawing")
arm = Arm("openmanipulator_x", "sim", world=World())
job = draw(
    arm, scene, HERE / "scripts" / "square.svg", "A5", preview="plan.png", result="drawn.png"
)
print("\n".join(job.lines()))  # ... drawn: Hausdorff 0.20 mm, RMS cross-track 0.05 mm, ...
