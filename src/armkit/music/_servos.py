"""Which servos an arm has, as music needs to know them: how their moves are timed
(the planner's predictors), how long their position loop lags a ramp, and when a
rebound is sent. Told apart by how the driver's moves run (``Forecaster.moves``):
music does not import the drivers."""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from .._errors import InputError
from ..arm import Start
from ..model import ArmModel
from ._predict import (
    Predictor,
    Rebound,
    group_move_predictor,
    rebound_of,
    time_based_predictor,
    timed_predictor,
)

F64 = NDArray[np.float64]

# The servos' position loop: following a ramp, a servo lags it by its time constant
# [s]. These are the simulated servos' (armkit.sim: smart 10 ms, hobby 25 ms); a
# calibration run on a real arm (``LatencyTable.from_run``) measures its own.
SERVO_LAG = {"dynamixel": 0.010, "hobby": 0.025}
# The rebound is sent this long before the lagging head reaches the top [s]: the servos'
# position loop carries the head on through the top for a few ms after it (the contact
# lands as planned), and the sooner it turns the shorter it stays below the top
# (measured in the simulator: 14-16 ms on the XM430s). The SSC-32's group move turns
# the hobby servos' goal at once, so their rebound is sent as the head reaches the top:
# sent 5 ms before, the Lynx6's slowest strokes (0.1 m/s at the head, bars 180-200 mm
# from the base) turned 0.01 mm above or below the top and were missed or heard at a
# tenth of their speed; sent on time the head goes 0.5-0.8 mm through (33-35 ms below).
REBOUND_LEAD = {"dynamixel": 0.002, "hobby": 0.0}
SERVOS = {"smart": "dynamixel", "hobby": "hobby"}  # a driver's moves -> its servos


def servo_kind(start: Start) -> str:
    """``"dynamixel"`` or ``"hobby"``: the servos of the arm ``start`` is planned on, by how
    its driver's moves run (``Forecaster.moves``: the arm's own driver, or for a model
    alone its own driver kind's, as ``armkit check`` plans it); InputError for a driver
    that cannot time its moves."""
    kind = SERVOS.get(start.timer.moves)
    if kind is None:
        raise InputError(
            f"playing needs servos that time their moves (Dynamixel, SSC-32 or Maestro); the "
            f"{start.model.name}'s motors ({start.timer.moves}) cannot land a strike on the beat"
        )
    return kind


def predictors(kind: str, model: ArmModel) -> tuple[Predictor, Rebound, float, float]:
    """The predictors of servos of ``kind`` (``servo_kind``): the motion model of their
    moves and of their rebound, their lag [s] and the ``REBOUND_LEAD`` [s], at the servos'
    own limits (``ArmModel.at_servo_limits``: every move of a piece is sent with its
    duration, which a servo may fill up to its own speed and acceleration)."""
    model = model.at_servo_limits()
    if kind == "dynamixel":
        return (
            time_based_predictor(model),
            timed_predictor(model),
            SERVO_LAG[kind],
            REBOUND_LEAD[kind],
        )
    group = group_move_predictor(model)
    return group, rebound_of(group), SERVO_LAG["hobby"], REBOUND_LEAD["hobby"]
