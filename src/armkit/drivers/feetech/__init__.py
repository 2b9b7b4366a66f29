"""The Feetech STS bus driver (SO-101, SO-100): ``open_feetech``, ``FeetechDriver``,
its forecasts without a device (``FeetechForecaster``) and its calibration as points
for the simulator (``feetech_points``)."""

from ._driver import FeetechDriver as FeetechDriver
from ._driver import open_feetech as open_feetech
from ._forecast import FeetechForecaster as FeetechForecaster
from ._points import feetech_points as feetech_points
