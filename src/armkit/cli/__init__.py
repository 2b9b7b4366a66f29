"""The ``armkit`` command line. Each command group lives in its own module."""

from ._app import main as main
