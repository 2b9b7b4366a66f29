"""Seed 002's search on the Lynx6: a Sharp GP2D120 distance sensor on the hand,
read through the SSC-32's analog input VA (the simulated one answers the real
``VA`` query with one byte, 0..255 for 0..5 V). The arm scans 30..120 deg in
5 deg steps for a local maximum of the sensor's voltage, scans back over it in
1 deg steps, aligns with its middle, measures the distance, picks the object
up, drops it in the bin, goes home (and switches the servos off where the
driver can).

On an arm without an SSC-32 (try "openmanipulator_x") the same sensor is read
through a serial ADC board that prints its readings; in the simulator its
emulator runs on a pseudo-terminal and the reading side is pyserial.

Run: .venv/bin/python examples/27_search.py
"""

from __future__ import annotations

from armkit import Arm, tasks
from armkit.scene import load_scene

scene = load_scene("search_002")
with Arm("lynx6", "sim") as arm:
    result = tasks.search(arm, scene, start=30.0, stop=120.0, into="bin")  # deg
    print("\n".join(result.lines()))
    truth = scene.cube("object").position * 1000
    print(f"the object really was at ({truth[0]:.1f}, {truth[1]:.1f}) mm")
    for angle, volts in result.readings[:5]:
        print(f"  {angle:5.1f} deg  {volts:.2f} V")
