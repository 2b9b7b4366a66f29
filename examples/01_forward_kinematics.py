"""Forward kinematics: where is the gripper for these joint angles?

Run: .venv/bin/python examples/01_forward_kinematics.py
"""

import math

import numpy as np

import armkit

model = armkit.load_model("owi535")
angles_deg = {
    "base": 20.0,
    "shoulder": 30.0,
    "elbow": 60.0,
    "wrist": 0.0,
}  # wrist = 90 - 30 - 60: level
q = np.radians([angles_deg[name] for name in model.joint_names])  # the core works in radians

T = armkit.fk(model, q)  # 4x4 pose of the gripper point, metres
x, y, z = T[:3, 3] * 1000
print(f"{model.name} at {angles_deg}")
print(
    f"  gripper at x={x:.1f} y={y:.1f} z={z:.1f} mm, pitch {math.degrees(armkit.pitch_of(T)):.1f} deg"
)

frames = armkit.fk_frames(model, q)  # every joint frame, for drawing axes
for name, F in zip(["world", *model.joint_names, "tool"], frames, strict=True):
    print(f"  {name:8s} origin {np.round(F[:3, 3] * 1000, 1)} mm")
