"""Putting a simulated arm together: its body in a world, its controller, its state file.

The factory (``armkit.connect``) calls these with what only it knows (which
channel turns which joint, from the driver's calibration: ``Mount``s); nothing
here knows a driver.
"""

from __future__ import annotations

import contextlib
from collections.abc import Callable, Sequence
from pathlib import Path

import numpy as np

from .._lock import exclusive
from ..model import ArmModel
from ._arm import SimArm, Truth
from ._pulses import PulseOutputs
from ._servo_body import Mount, Outputs, ServoBody, ServoParams
from ._state import load_truth, save_truth
from ._world import World
from .dynamixel import SimDynamixelBus
from .feetech import SimFeetechBus
from .owi535 import OwiBody
from .owi_physics import OwiPhysics, random_unit

SETTLE_LIMIT_S = 30.0  # longest a closing simulation waits for its arm to come to rest [s]


def home_truth(model: ArmModel) -> Truth:
    """The arm at home, gripper open."""
    return Truth(tuple(float(a) for a in model.home), model.gripper.width_max)


def params_for(model: ArmModel) -> ServoParams:
    """Servo behaviour: smart servos (Dynamixel) lag less than hobby servos."""
    smart = "dynamixel" in model.drivers or "feetech" in model.drivers
    return ServoParams(lag=0.010) if smart else ServoParams(lag=0.025)


def add_servo_arm(
    world: World,
    model: ArmModel,
    outputs: Outputs,
    mounts: Sequence[Mount],
    *,
    truth: Truth | None = None,
    params: ServoParams | None = None,
    name: str | None = None,
) -> SimArm:
    """An arm of servos driven by ``outputs`` through ``mounts``, added to ``world``.
    A Dynamixel bus's servos read their positions back from the arm. Given a ``truth``
    (the arm as a previous process left it), the controller was never switched off:
    every channel still holds the arm where it is."""
    start = truth or home_truth(model)
    body = ServoBody(model, params or params_for(model), start, mounts)
    body.outputs = outputs
    if isinstance(outputs, SimDynamixelBus | SimFeetechBus):
        for mount in mounts:
            _link_encoder(outputs, body, mount)
    elif isinstance(outputs, PulseOutputs) and truth is not None:
        for mount in mounts:
            pulse = round(4 * mount.from_si(body.position(mount.joint))) / 4
            outputs.go(mount.channel, pulse, 0.0, world.now())
    return world.add_arm(SimArm(model, body, world.unique_name(name or model.name)))


def _link_encoder(bus: SimDynamixelBus | SimFeetechBus, body: ServoBody, mount: Mount) -> None:
    servo = bus.servos[mount.channel]

    def feedback() -> tuple[float, float]:
        return mount.from_si(body.position(mount.joint)), body.speed(mount.joint) * mount.slope

    tick = round(mount.from_si(body.position(mount.joint)))
    body.place(mount.joint, mount.to_si(tick))  # a servo with torque rests on a tick
    servo.hold_at(tick)
    servo.feedback = feedback


def add_owi_arm(
    world: World,
    model: ArmModel,
    *,
    truth: Truth | None = None,
    seed: int = 0,
    name: str | None = None,
) -> tuple[SimArm, OwiPhysics]:
    """A simulated OWI-535 unit (drawn with ``seed``) in ``world``: its arm and its motors."""
    start = truth or Truth(tuple(float(a) for a in model.home), model.gripper.width_min)
    physics = OwiPhysics(model, random_unit(model, seed), world.clock, seed, np.array(start.q))
    body = OwiBody(model, physics)
    body.restore(start)
    arm = world.add_arm(SimArm(model, body, world.unique_name(name or model.name)))
    return arm, physics


def settle(world: World, arm: SimArm, limit_s: float = SETTLE_LIMIT_S) -> None:
    """Run ``world`` until ``arm`` is at rest (as the servos do after a program exits),
    at most ``limit_s`` [s] of simulated time."""
    deadline = world.now() + limit_s
    while not arm.at_rest() and world.now() < deadline:
        world.advance(0.01)


class Persistence:
    """A simulated arm tied to its state file: taken (locked) at open, written at close."""

    def __init__(self, path: Path, model: ArmModel, what: str) -> None:
        self.path, self.model = path, model
        self.start: Truth | None = None
        self._lock = exclusive(path, what)
        try:
            self.truth = load_truth(path, model)
        except BaseException:
            self._lock.release()
            raise

    def closer(self, world: World, arm: SimArm) -> Callable[[], None]:
        """The action that settles ``arm``, writes its truth if it changed since now, and
        gives the file back; the kept tool is put back in ``arm``'s gripper first."""
        if self.truth is not None and self.truth.tool is not None:
            arm.hold_tool(self.truth.tool)
        self.start = arm.truth()

        def close() -> None:
            try:
                with contextlib.suppress(Exception):
                    settle(world, arm)
                truth = arm.truth()
                if truth != self.start:  # a refused command leaves no file behind
                    save_truth(self.path, self.model, truth)
            finally:
                self._lock.release()

        return close

    def release(self) -> None:
        """Give the file back without writing (opening failed)."""
        self._lock.release()
