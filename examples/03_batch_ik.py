"""Batch inverse kinematics: a million targets a second, with the failures named.

Run: .venv/bin/python examples/03_batch_ik.py
"""

import time

import numpy as np

import armkit

model = armkit.load_model("openmanipulator_x")
rng = np.random.default_rng(0)
xs = np.linspace(0.10, 0.40, 200)
ys = np.linspace(-0.15, 0.15, 200)
grid = np.array([(x, y, 0.03) for x in xs for y in ys])  # 40,000 points 30 mm above the table

t0 = time.perf_counter()
res = armkit.ik_batch(model, grid, pitches=np.radians(-90))  # all from above
dt = time.perf_counter() - t0
print(f"{len(grid)} targets in {dt * 1000:.1f} ms ({len(grid) / dt / 1e6:.2f} M/s)")
print(f"reachable from above: {res.ok.mean() * 100:.1f} %")
for reason in ("too_far", "too_close", "joint_limit"):
    print(f"  {reason:11s} {(res.reason == reason).sum()}")
err = np.abs(armkit.fk(model, res.q[res.ok])[:, :3, 3] - grid[res.ok]).max()
print(f"largest error of the solved ones, by FK: {err * 1000:.1e} mm")
