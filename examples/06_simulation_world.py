"""The simulation world: watch the true arm with an observer, and grasp a simulated cube.

``Arm(..., driver="sim")`` runs the arm's real driver on a simulated device in a
``World``: the one place where the arm's true joint angles live. An observer is
called after every 1 ms step of simulated time; here one traces how low the
gripper goes, and another plays a cube between the jaws: when the closing jaws
reach its width it stops them there (``SimArm.grip_stop``), as a scene would.

Run: .venv/bin/python examples/06_simulation_world.py
"""

from __future__ import annotations

import math

from armkit import Arm
from armkit.kinematics import fk
from armkit.sim import SimArm, World

CUBE_MM = 30.0


class LowestPoint:
    """Observer: the lowest the gripper point has been [m] (checked at 100 Hz)."""

    def __init__(self, arm: SimArm) -> None:
        self.arm, self.lowest, self.next_t = arm, math.inf, 0.0

    def on_step(self, world: World, t: float) -> None:
        if t >= self.next_t:  # an observer that needs less than 1 kHz checks the time itself
            self.next_t = t + 0.01
            self.lowest = min(self.lowest, float(fk(self.arm.model, self.arm.q())[2, 3]))


class CubeInTheJaws:
    """Observer: a cube of ``CUBE_MM`` between the jaws stops them when they reach it."""

    def __init__(self, arm: SimArm) -> None:
        self.arm = arm

    def on_step(self, world: World, t: float) -> None:
        if self.arm.grip() <= CUBE_MM / 1000.0 + 1e-4:
            self.arm.grip_stop(CUBE_MM / 1000.0)


world = World()
with Arm("openmanipulator_x", driver="sim", world=world) as arm:
    truth = world.arm()
    lowest = LowestPoint(truth)
    world.attach(lowest)
    world.attach(CubeInTheJaws(truth))
    arm.approach(200, 0, 20, pitch=-90)  # down onto the cube
    arm.grip(20)  # close as far as it goes: the cube is in the way
    print(
        f"simulated {world.now():.2f} s; the gripper went down to z {lowest.lowest * 1000:.1f} mm"
    )
    print(f"asked for a 20 mm grip, the jaws stopped at {truth.grip() * 1000:.1f} mm on the cube")
    arm.retreat()
    print(f"true joints now (deg): {[round(math.degrees(a), 2) for a in truth.q()]}")
