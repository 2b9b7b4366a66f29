"""Calibration by the routine a person runs, answered by the automatic operator;
re-homing; and the drift it buys over 000's constant-rate model."""

from __future__ import annotations

import math

import numpy as np
import pytest

from armkit.devices.owi535 import open_device
from armkit.drivers.timed import (
    TimedDriver,
    calibrate_owi535,
    constant_rate,
    load_state,
    rehome,
    state_path,
)
from armkit.kinematics import fk
from armkit.model import ArmModel
from armkit.sim.owi_operator import SimOperator, auto_operator
from armkit.sim.owi_sim import OwiSim, build_sim

DEG = math.radians
MOVES = [
    np.radians(q)
    for q in (
        [30, 40, 60, -10],
        [-50, 20, 80, -10],
        [60, 50, 40, 0],
        [-20, 10, 70, 10],
        [0, 45, 45, 0],
    )
]


def calibrated(owi: ArmModel, seed: int, name: str = "cal") -> tuple[TimedDriver, OwiSim]:
    sim = build_sim(owi, seed)
    driver = TimedDriver(
        owi, open_device(sim.backend), sim.clock, state_path(f"{name}{seed}"), durable=False
    )
    operator = SimOperator(sim, seed)
    assert calibrate_owi535(owi, driver, operator.ask, operator.say) == driver.path
    return driver, sim


def test_calibration_writes_a_certain_fitted_state(owi: ArmModel) -> None:
    driver, sim = calibrated(owi, 11)
    state = load_state(driver.path)
    assert state.calibrated and not state.uncertain and state.pending is None
    unit = sim.physics.unit
    base_true = unit.speed[0] * (1 + unit.asym[0])  # forwards, full battery
    assert state.timing.joints[0].rates[0] == pytest.approx(base_true, rel=0.03)
    assert state.timing.drain == pytest.approx(unit.drain, rel=0.3)
    assert set(state.extra["traverse_s"]) == {"base", "shoulder", "elbow", "wrist"}
    driver.close()


def test_calibrated_model_drifts_less_than_000s(owi: ArmModel) -> None:
    errors = {}
    for kind in ("000", "armkit"):
        driver, sim = calibrated(owi, 5, kind)
        if kind == "000":
            timing = constant_rate(owi, driver.state.extra["traverse_s"])
            driver.set_state(driver.state.with_(timing=timing))
        driver.set_state(driver.state.with_(angles=tuple(sim.physics.true_q())))
        for q in MOVES:
            driver.move(q)
        errors[kind] = np.linalg.norm(
            fk(owi, driver.read())[:3, 3] - fk(owi, sim.physics.true_q())[:3, 3]
        )
        driver.close()
    assert errors["armkit"] < errors["000"] / 3


def test_rehome_makes_an_uncertain_state_certain_again(owi: ArmModel) -> None:
    driver, sim = calibrated(owi, 2)
    driver.move(np.radians([40.0, 30.0, 60.0, 0.0]))
    lost = (DEG(-20), DEG(10), DEG(90), DEG(30))  # what a kill -9 might leave
    driver.set_state(driver.state.with_(angles=lost, uncertain=True, reason="lost"))
    rehome(driver, say=lambda _text: None)
    assert not driver.state.uncertain and driver.state.reason == "re-homed"
    assert np.allclose(driver.read(), 0.0)
    assert np.all(np.abs(sim.physics.true_q()) < DEG(6))
    driver.close()


def test_auto_operator_only_on_the_simulator(owi: ArmModel, driver: TimedDriver) -> None:
    from armkit.connect import open_driver

    sim_driver = open_driver(owi, "sim")
    assert isinstance(auto_operator(sim_driver), SimOperator)
    assert auto_operator(driver) is None
    sim_driver.close()
