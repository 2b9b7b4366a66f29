"""Drivers: joint angles <-> device commands (timing model, pulse tables, ticks).

``Driver`` is the interface and its contract. A driver is opened, on real
hardware or on a simulated device, by the factory: ``armkit.connect.open_driver``
(or ``armkit.Arm``); ``driver_names()`` lists the drivers of real hardware.
"""

from ._driver import Driver as Driver
from ._driver import PathFollower as PathFollower
from ._registry import DRIVERS as DRIVERS
from ._registry import driver_names as driver_names
from ._registry import open_driver as open_driver
