"""Child process for the Ctrl-Z test: a simulated OWI on the real clock, every
command logged; one long move. A suspension stops it: the child writes its
estimate, the truth and the motor time, and exits 3."""

from __future__ import annotations

import math
import sys
from pathlib import Path

from armkit.devices.owi535 import open_device
from armkit.drivers.timed import TimedDriver, WallClock, _safety, state_path
from armkit.model import load_model
from armkit.sim.owi_sim import build_sim


def main(log: str, out: str) -> int:
    model = load_model("owi535")
    clock = WallClock()
    sim = build_sim(model, 3, clock=clock, log_path=Path(log))
    driver = TimedDriver(model, open_device(sim.backend), clock, state_path("suspend"), "suspend")
    driver.set_light(True)
    code = 0
    try:
        driver.turn_to("base", math.radians(130))  # ~8 s: long enough to be suspended
    except getattr(_safety, "Suspended", ()) as exc:  # (older armkits have no Suspended)
        print(exc, file=sys.stderr)
        code = 3
    Path(out).write_text(f"{driver.read()[0]} {sim.physics.true_q()[0]} {driver.state.motor_s}\n")
    driver.close()
    return code


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2]))
