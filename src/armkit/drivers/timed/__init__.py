"""The OWI-535's driver: timed motors, joints that know their angle, a
calibrated timing model and a state file that is never lost (seed 000).

``forecast_move``, ``forecast_run``, ``grip_seconds`` and ``plan_path_runs`` tell
what the driver will do (its runs, their times, the estimate after them) without a
device: the script checker times OWI scripts with them. A path (a straight line, a
drawing) is not streamed to timed motors but followed through waypoints they can
make (``TimedDriver.follow_path``, ``path_waypoints``)."""

from __future__ import annotations

from ..._clock import Clock as Clock
from ..._clock import WallClock as WallClock
from ...model import ArmModel
from ._calibrate import calibrate_owi535 as calibrate_owi535
from ._config import constant_rate as constant_rate
from ._config import default_timing as default_timing
from ._driver import TimedDriver as TimedDriver
from ._forecast import TurnForecast as TurnForecast
from ._forecast import forecast_move as forecast_move
from ._forecast import forecast_run as forecast_run
from ._forecast import grip_seconds as grip_seconds
from ._forecaster import TimedForecaster as TimedForecaster
from ._journal import UncertainEstimateWarning as UncertainEstimateWarning
from ._keys import run_keys as run_keys
from ._keys import status_line as status_line
from ._plan import MoveReport as MoveReport
from ._plan import ShortMoveError as ShortMoveError
from ._plan import Turn as Turn
from ._rehome import rehome as rehome
from ._state import UnitState as UnitState
from ._state import load as load_state
from ._state import state_path as state_path
from ._timing import JointTiming as JointTiming
from ._timing import TimingModel as TimingModel
from ._waypoints import PATH_TOLERANCE as PATH_TOLERANCE
from ._waypoints import PathRuns as PathRuns
from ._waypoints import path_waypoints as path_waypoints
from ._waypoints import plan_path_runs as plan_path_runs

__all__ = [
    "PATH_TOLERANCE",
    "Clock",
    "JointTiming",
    "MoveReport",
    "PathRuns",
    "ShortMoveError",
    "TimedDriver",
    "TimedForecaster",
    "TimingModel",
    "Turn",
    "TurnForecast",
    "UncertainEstimateWarning",
    "UnitState",
    "calibrate_owi535",
    "constant_rate",
    "default_timing",
    "forecast_move",
    "forecast_run",
    "grip_seconds",
    "load_state",
    "open_owi535",
    "path_waypoints",
    "plan_path_runs",
    "rehome",
    "run_keys",
    "state_path",
    "status_line",
]  # fmt: skip


def open_owi535(model: ArmModel, port: str | None = None) -> TimedDriver:
    """The real arm over USB; ``port`` names the unit whose state file is used
    (None = ``"default"``), for people with several arms."""
    from ...devices.owi535 import open_device

    unit = port or "default"
    return TimedDriver(model, open_device(), WallClock(), state_path(unit), unit)
