"""The Feetech STS bus driver (SO-101, SO-100): ``open_feetech``, ``FeetechDriver``,
its forecasts without a device (``FeetechForecaster``), its calibration as points
for the simulator (``feetech_points``) and a unit's calibration in LeRobot's files."""

from ._calibrate import calibrate_feetech as calibrate_feetech
from ._driver import FeetechDriver as FeetechDriver
from ._driver import open_feetech as open_feetech
from ._forecast import FeetechForecaster as FeetechForecaster
from ._lerobot import MotorCalibration as MotorCalibration
from ._lerobot import calibrated as calibrated
from ._lerobot import calibration_path as calibration_path
from ._lerobot import calibration_text as calibration_text
from ._lerobot import read_calibration as read_calibration
from ._lerobot import unit_config as unit_config
from ._lerobot import write_calibration as write_calibration
from ._points import feetech_points as feetech_points
