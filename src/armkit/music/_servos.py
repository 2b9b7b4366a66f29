"""Which servos an arm has, as music needs to know them: how their moves are timed
(the planner's predictors), how long their position loop lags a ramp, and when a
rebound is sent. Told apart by the driver's methods: music does not import the
drivers."""

from __future__ import annotations

from typing import TYPE_CHECKING, Protocol, runtime_checkable

import numpy as np
from numpy.typing import NDArray

from .._errors import InputError
from ..connect import kinds_of
from ..model import ArmModel
from ._predict import (
    Predictor,
    Rebound,
    group_move_predictor,
    rebound_of,
    time_based_predictor,
    timed_predictor,
)

if TYPE_CHECKING:
    from ..arm import Arm

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


@runtime_checkable
class _ProfileServos(Protocol):
    """A Dynamixel driver (``drivers.dynamixel``): one time-based profile per move."""

    def to_ticks(self, q: F64) -> NDArray[np.int64]: ...
    def relax(self) -> None: ...


@runtime_checkable
class _GroupMoveServos(Protocol):
    """A hobby-servo driver (``drivers.servo``, SSC-32 or Maestro): one group move per move."""

    def move_servo(self, name: str, pulse_us: float, *, speed: float, wait: bool) -> None: ...


def predictor_for(arm: Arm, model: ArmModel) -> tuple[Predictor, Rebound, float, float]:
    """The motion model of the arm's servos (Dynamixel time-based profiles, or
    hobby-servo group moves, told apart by the driver's methods: music does not
    import the drivers), of their rebound (on Dynamixels a profile sent with its
    duration: Profile Velocity and Acceleration set per strike), their lag [s] and
    the ``REBOUND_LEAD`` [s]; InputError for a driver that cannot time its moves."""
    return predictors(servo_kind(arm), model)


def servo_kind(arm: Arm) -> str:
    """``"dynamixel"`` or ``"hobby"``: the arm's servos, by its driver's methods;
    InputError for a driver that cannot time its moves."""
    if isinstance(arm.driver, _ProfileServos):
        return "dynamixel"
    if isinstance(arm.driver, _GroupMoveServos):
        return "hobby"
    raise InputError(
        f"playing needs servos that time their moves (Dynamixel, SSC-32 or Maestro); the "
        f"{arm.model.name}'s {type(arm.driver).__name__} cannot land a strike on the beat"
    )


def model_servos(model: ArmModel) -> str:
    """``"dynamixel"`` or ``"hobby"``: the servos of an arm known only by its model (its
    drivers, as the model file lists them: what ``armkit check`` plans a piece with);
    InputError for an arm with neither."""
    traits = {trait for kind in kinds_of(model) for trait in kind.traits}
    if "smart" in traits:
        return "dynamixel"
    if "hobby" in traits:
        return "hobby"
    raise InputError(
        f"playing needs servos that time their moves (Dynamixel, SSC-32 or Maestro); the "
        f"{model.name}'s drivers ({', '.join(model.drivers) or 'none'}) cannot land a strike "
        "on the beat"
    )


def predictors(kind: str, model: ArmModel) -> tuple[Predictor, Rebound, float, float]:
    """``predictor_for`` of servos of ``kind`` (``servo_kind``, ``model_servos``), at the
    servos' own limits (``ArmModel.at_servo_limits``: every move of a piece is sent with
    its duration, which a servo may fill up to its own speed and acceleration)."""
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


def is_hobby(arm: Arm) -> bool:
    """True when the arm's servos are hobby servos (every move a timed group move)."""
    return isinstance(arm.driver, _GroupMoveServos)
