"""Draw an arm in a pose with every joint's axis indicators (needs the plot extra).

Run: .venv/bin/python examples/04_plot_pose.py  -> writes lynx6_pose.png
"""

import math

import numpy as np

import armkit
from armkit.viz import plot_pose

model = armkit.load_model("lynx6")
q = armkit.ik(model, (0.18, 0.08, 0.06), math.radians(-45)).q
path = plot_pose(model, q, "lynx6_pose.png")
print(f"wrote {path} (joint angles {np.degrees(q).round(1)} deg)")
