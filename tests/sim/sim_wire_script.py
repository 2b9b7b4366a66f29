"""One fixed job on every shipped arm with ``--driver sim``; prints JSON of what happened.

Run by the tests twice: in the test environment (pyserial, pyusb and the
dynamixel-sdk installed: the simulated devices plug in under them) and in a
virtual environment with only numpy (the same driver classes on the same
simulated devices through armkit's own narrow interfaces). The two outputs must
be identical: the same driver class, the same bytes on every wire, the same
true pose at the end.

    python sim_wire_script.py  ->  {"<arm>": {"driver": ..., "wire": [hex, ...], ...}, ...}
"""

from __future__ import annotations

import importlib.util
import json
import sys
from typing import Any

import numpy as np

from armkit.connect import open_driver, world_of
from armkit.model import ArmModel, load_model, shipped_models


def wire(device: Any) -> list[str]:
    """Everything ``device`` received, as hex strings, in order."""
    for name in ("transfers", "frames", "received"):
        log = getattr(device, name, None)
        if log is not None and not isinstance(log, int):
            return [getattr(item, "data", item).hex() for item in log]
    raise TypeError(f"no log on {device!r}")


def targets(model: ArmModel) -> list[np.ndarray]:
    """Two poses near home, inside the limits (small: the OWI keeps off the table)."""
    span = model.upper - model.lower
    signs = np.array([(-1.0) ** k for k in range(model.dof)])
    near = np.clip(model.home + 0.06 * span * signs, model.lower, model.upper)
    return [near, model.home]


def job(name: str) -> dict[str, Any]:
    """Open the arm's simulated driver, read, move twice, grip, close; what happened."""
    model = load_model(name)
    driver = open_driver(model, "sim")
    world = world_of(driver)
    assert world is not None
    first, back = targets(model)
    driver.read()
    driver.move(first, speed=0.5)
    g = model.gripper
    driver.grip(g.width_min + 0.6 * (g.width_max - g.width_min))
    driver.move(back)
    arm = world.arm()
    q = [round(float(a), 9) for a in arm.q()]
    driver.close()
    return {"driver": type(driver).__name__, "wire": wire(arm.device), "q": q}


def libraries() -> dict[str, bool]:
    """Which client libraries this environment has."""
    return {
        lib: importlib.util.find_spec(lib) is not None
        for lib in ("serial", "usb", "dynamixel_sdk", "scservo_sdk")
    }


def main() -> None:
    report = {"libraries": libraries(), "arms": {name: job(name) for name in shipped_models()}}
    json.dump(report, sys.stdout)


if __name__ == "__main__":
    main()
