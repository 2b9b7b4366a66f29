"""Drivers: joint angles <-> device commands (timing model, pulse tables, ticks)."""

from ._driver import Driver as Driver
