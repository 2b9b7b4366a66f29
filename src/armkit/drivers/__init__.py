"""Drivers: joint angles <-> device commands (timing model, pulse tables, ticks)."""

from ._driver import Driver as Driver
from ._registry import driver_names as driver_names
from ._registry import open_driver as open_driver
