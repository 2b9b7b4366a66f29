"""Teach by hand: the shell's ``limp`` and ``hold`` on the simulated OpenManipulator-X.

``limp`` switches the XM430s' torque off; a hand moves the arm (on the
simulator: ``SimArm.push``, which only moves joints whose torque is off);
``save`` reads the true angles over the Dynamixel bus; ``hold`` switches the
torque on where the arm is; ``write`` makes a script that ``armkit run`` replays.
On the Lynx6 (SSC-32) and the OWI, ``limp`` is refused: nothing can read a pose
moved by hand there.

Run: .venv/bin/python examples/29_teach_by_hand.py
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from armkit import Arm
from armkit.script import Session, Source, run_source

HAND_DEG = ([30.0, -30.0, 20.0, 40.0], [-45.0, 0.0, 10.0, 30.0])  # where the hand puts it

with Arm("openmanipulator_x") as arm:  # the simulated arm
    shell = Session(arm, base_dir=Path.cwd())
    print(shell.handle("limp").text)
    hand = arm.world.arm() if arm.world is not None else None
    assert hand is not None, "this example runs on the simulator"
    for k, angles in enumerate(HAND_DEG, 1):
        hand.push(np.radians(angles))  # a person moves the limp arm
        print(shell.handle(f"save by_hand_{k}").text)
    print(shell.handle("hold").text)
    print(shell.handle("move by_hand_1").text or "moved back to by_hand_1")
    print(shell.handle("write by_hand.arm").text)

with Arm("openmanipulator_x") as arm:
    run_source(arm, Source("by_hand.arm", Path("by_hand.arm").read_text(encoding="utf-8")))
    error = np.degrees(np.max(np.abs(arm.driver.read() - np.radians(HAND_DEG[0]))))
    print(f"replayed by_hand.arm: ends {error:.3f} deg from by_hand_1 (max over the joints)")
    assert error < 0.1, error

with Arm("lynx6") as lynx:  # hobby servos report nothing: the shell refuses, on purpose
    print("on the Lynx6, as expected:", Session(lynx).handle("limp").text)
