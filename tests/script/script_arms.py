"""An arm on the simulator whose driver counts every command that reaches it (only
the public ``Arm`` API and ``driver.read()`` are used, so this survives a new simulator)."""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import NDArray

from armkit import Arm
from armkit.connect import open_driver
from armkit.model import load_model


class CountingDriver:
    """Passes everything to a real driver and counts what would make the arm act."""

    def __init__(self, inner: Any) -> None:
        self.inner = inner
        self.sent = 0
        self.clock = inner.clock

    @property
    def joint_names(self) -> tuple[str, ...]:
        return tuple(self.inner.joint_names)

    def move(self, q: NDArray[np.float64], **options: Any) -> None:
        self.sent += 1
        self.inner.move(q, **options)

    def grip(self, width: float) -> None:
        self.sent += 1
        self.inner.grip(width)

    def read(self) -> NDArray[np.float64]:
        return np.asarray(self.inner.read(), dtype=np.float64)

    def stop(self) -> None:
        self.inner.stop()

    def close(self) -> None:
        self.inner.close()

    def __getattr__(self, name: str) -> Any:  # turn_for, set_light on the OWI
        attr = getattr(self.inner, name)
        if callable(attr) and name in ("turn_for", "set_light"):

            def counted(*args: Any, **kwargs: Any) -> Any:
                self.sent += 1
                return attr(*args, **kwargs)

            return counted
        return attr


def counting_arm(name: str = "openmanipulator_x") -> tuple[Arm, CountingDriver]:
    """An ``Arm`` on the simulator with a counting driver."""
    model = load_model(name)
    driver = CountingDriver(open_driver(model, "sim"))
    return Arm(model, driver), driver  # type: ignore[arg-type]
