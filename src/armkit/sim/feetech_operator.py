"""An automatic person for calibrating the simulated SO-101: asked to hold the arm in
the middle of its range it puts every joint at 0 (the URDF's zero is the middle, as
LeRobot's calibration makes it); asked to move a joint to one end, then the other, it
puts that joint at its lower, then its upper limit (the others in the middle), the jaws
shut, then open
(``SimArm.push``, ``push_grip``: the torque is off)."""

from __future__ import annotations

import numpy as np

from ._arm import SimArm


class FeetechOperator:
    """``ask`` for ``armkit.drivers.feetech.calibrate_feetech`` on a simulated arm."""

    def __init__(self, arm: SimArm) -> None:
        self.arm = arm
        self.lines: list[str] = []

    def ask(self, prompt: str) -> str:
        """Do what the prompt asks with the simulated arm; answer ''."""
        self.lines.append(prompt)
        model = self.arm.model
        q = np.zeros(model.dof)  # the middle, every joint but the one it moves
        for j, name in enumerate(model.joint_names):
            if f"Move {name} by hand to one end" in prompt:
                q[j] = model.lower[j]
            elif f"Move {name} by hand to the other end" in prompt:
                q[j] = model.upper[j]
        self.arm.push(np.asarray(q, dtype=np.float64))
        g = model.gripper
        if "Move gripper by hand to one end" in prompt:
            self.arm.push_grip(g.width_min)
        elif "Move gripper by hand to the other end" in prompt:
            self.arm.push_grip(g.width_max)
        return ""
