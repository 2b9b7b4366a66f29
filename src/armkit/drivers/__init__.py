"""Drivers: joint angles <-> device commands (timing model, pulse tables, ticks).

``Driver`` is the interface and its contract. A driver is opened, on real
hardware or on a simulated device, by the factory: ``armkit.connect.open_driver``
(or ``armkit.Arm``), from its kind's entry in the registry ``armkit.connect.driver_kinds()``.
"""

from ._driver import Driver as Driver
from ._driver import Forecast as Forecast
from ._driver import Forecaster as Forecaster
from ._driver import PathFollower as PathFollower
from ._driver import PathForecaster as PathForecaster
from ._driver import RunForecaster as RunForecaster
from ._driver import TimedMotors as TimedMotors
