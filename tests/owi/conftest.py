"""Fixtures for the OWI-535 tests: a private config directory and a simulated arm
driven by the real driver through the simulated pyusb device."""

from __future__ import annotations

from collections.abc import Iterator

import pytest

from armkit.devices.owi535 import open_device
from armkit.drivers.timed import TimedDriver, state_path
from armkit.model import ArmModel, load_model
from armkit.sim.owi_sim import OwiSim, build_sim


@pytest.fixture
def owi() -> ArmModel:
    return load_model("owi535")


@pytest.fixture
def sim(owi: ArmModel) -> OwiSim:
    return build_sim(owi, seed=7)


@pytest.fixture
def driver(owi: ArmModel, sim: OwiSim) -> Iterator[TimedDriver]:
    d = TimedDriver(
        owi, open_device(sim.backend), sim.clock, state_path("test"), "test", durable=False
    )
    yield d
    d.close()


from owi_wire import sent as sent  # noqa: E402  (kept importable from here too)
