"""Inverse kinematics: which joint angles put the gripper here?

Every branch is returned, best (nearest the current pose) first; a target the
arm cannot reach raises UnreachableError saying why.

Run: .venv/bin/python examples/02_inverse_kinematics.py
"""

import math

import numpy as np

import armkit

model = armkit.load_model("openmanipulator_x")
target_mm = (200.0, 50.0, 40.0)
result = armkit.ik(model, np.array(target_mm) / 1000, pitch=math.radians(-90))  # pick from above
print(f"{model.name}: {len(result.solutions)} solution(s) for {target_mm} mm, pitch -90 deg")
for q in result.solutions:
    print(
        "  "
        + ", ".join(f"{n} {a:7.2f}" for n, a in zip(model.joint_names, np.degrees(q), strict=True))
    )
print(f"  checked by FK: {result.position_error * 1000:.2e} mm off")

try:
    armkit.ik(model, (0.6, 0.0, 0.1))
except armkit.UnreachableError as exc:
    print(f"  600 mm away: {exc} (reason: {exc.reason})")

lynx = armkit.load_model("lynx6").with_grip_width(0.025)  # 002: the grip point moves with the width
q = armkit.ik(lynx, (0.2, 0.0, 0.05), math.radians(-60)).q
print(
    f"lynx6 servo angles for (200, 0, 50) mm, pitch -60, grip 25 mm open: {np.degrees(q).round(1)}"
)
