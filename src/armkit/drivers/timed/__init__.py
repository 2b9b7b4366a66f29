"""The OWI-535's driver: timed motors, joints that know their angle, a
calibrated timing model and a state file that is never lost (seed 000)."""

from __future__ import annotations

import numpy as np

from ..._clock import Clock as Clock
from ..._clock import WallClock as WallClock
from ...model import ArmModel
from ._calibrate import run_calibration as run_calibration
from ._config import constant_rate as constant_rate
from ._config import default_timing as default_timing
from ._driver import TimedDriver as TimedDriver
from ._journal import UncertainEstimateWarning as UncertainEstimateWarning
from ._plan import MoveReport as MoveReport
from ._plan import ShortMoveError as ShortMoveError
from ._rehome import rehome as rehome
from ._state import ArmState as ArmState
from ._state import load as load_state
from ._state import state_path as state_path
from ._timing import JointTiming as JointTiming
from ._timing import TimingModel as TimingModel

__all__ = [
    "ArmState", "Clock", "JointTiming", "MoveReport", "ShortMoveError",
    "TimedDriver", "TimingModel", "UncertainEstimateWarning", "constant_rate", "default_timing", "load_state",
    "open_driver", "open_sim_driver", "rehome", "run_calibration", "state_path",
]  # fmt: skip


def open_driver(model: ArmModel, port: str | None = None) -> TimedDriver:
    """The real arm over USB; ``port`` names the unit whose state file is used
    (None = ``"default"``), for people with several arms."""
    from ...devices.owi535 import open_device

    unit = port or "default"
    return TimedDriver(model, open_device(), WallClock(), state_path(unit), unit)


def open_sim_driver(model: ArmModel, port: str | None = None) -> TimedDriver:
    """The same driver on a simulated arm (simulated clock: moves take no real time).
    The simulated unit starts where its state file says it is."""
    from ...devices.owi535 import open_device
    from ...sim.owi_sim import build_sim

    unit = "sim" if port in (None, "emu") else f"sim-{port}"
    path = state_path(unit)
    q0 = load_state(path).angles if path.exists() else None
    sim = build_sim(model, 0, q0=None if q0 is None else np.array(q0))
    driver = TimedDriver(model, open_device(sim.backend), sim.clock, path, unit)
    driver.simulation = sim
    return driver
