"""The scan of 002's search: the hand held low at a fixed radius and pitch, its
sensor looking level across the table, turned through an arc by the base. The
pose is chosen per arm (the first radius and pitch that reaches the whole arc and
clears everything), every scan pose checked before the first motion."""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from ..kinematics import fk
from ..model import ArmModel
from ..scene import Scene
from ..sensing import DistanceSensor, SensorMount
from ._plan import TaskError
from ._run import settle
from ._state import Context, Options, State, moves, solve

if TYPE_CHECKING:
    from ..arm import Arm

F64 = NDArray[np.float64]
HEIGHT = 0.015  # [m] the beam's height above the table: across a 25 mm object
RADII = (0.11, 0.13, 0.09)  # [m] tried in order
PITCHES = tuple(math.radians(p) for p in (-60.0, -45.0, -75.0, -30.0, 0.0))
AHEAD = math.radians(90.0)  # 002's base servo angle looking straight ahead


@dataclass
class Scan:
    """A scan pose: the tool point ``radius`` [m] out and ``HEIGHT`` up at ``pitch``
    [rad], the sensor mounted to look level there; ``readings`` (angle [rad], V) so far."""

    kin: ArmModel
    scene: Scene
    radius: float
    pitch: float
    mount: SensorMount
    readings: list[tuple[float, float]] = field(default_factory=list)

    def point(self, angle: float) -> F64:
        """The tool point at 002 servo angle ``angle`` [rad], scene frame [m], (3,)."""
        az = angle - AHEAD
        base = np.array([self.radius * math.cos(az), self.radius * math.sin(az), HEIGHT])
        out: F64 = self.scene.to_scene(base + np.array([0.0, 0.0, self.scene.table_z]))
        return out

    def joints(self, angle: float, seed: F64) -> F64:
        """The joints [rad] (dof,) of the scan pose at ``angle``."""
        base = self.scene.to_base(self.point(angle))
        return solve(
            self.kin, base, self.pitch, seed, "search", f"scan at {math.degrees(angle):.0f} deg"
        )

    def sweep(self, arm: Arm, sensor: DistanceSensor, angles: F64) -> list[tuple[float, float]]:
        """Turn to each of ``angles`` [rad] and read the sensor: [(angle, volts)]."""
        out = []
        for a in angles:
            q = self.joints(float(a), arm.driver.read())
            arm.move_joints(np.degrees(q).tolist())
            settle(arm)  # the reading is taken standing still
            out.append((float(a), sensor.read()))
        self.readings.extend(out)
        return out

    def object_at(self, arm: Arm, angle: float, distance: float, size: float) -> F64:
        """The bottom centre [m] (3,) of a cube of ``size`` [m] whose near face the beam
        meets ``distance`` [m] out at ``angle`` [rad]."""
        q = self.joints(angle, arm.driver.read())
        origin, d = self.mount.beam(self.scene.T_world_base @ fk(self.kin, q))
        level = np.array([d[0], d[1], 0.0]) / max(float(np.hypot(d[0], d[1])), 1e-9)
        centre = origin + distance * d + level * size / 2.0
        return np.array([centre[0], centre[1], self.scene.table_z])


def plan_scan(arm: Arm, scene: Scene, start: float, stop: float, step: float) -> Scan:
    """The first scan pose (RADII x PITCHES) whose every coarse pose is reachable and
    whose moves through them are clear; nothing moves.

    Raises:
        TaskError: none is, naming the step of the first pose tried.
    """
    g = arm.model.gripper
    kin = arm.model.with_grip_width(g.width_max)
    n = max(1, round(abs(stop - start) / step))
    angles = np.linspace(start, stop, n + 1)
    ctx = Context(arm.model, Options(), "search")
    first: TaskError | None = None
    for radius in RADII:
        for pitch in PITCHES:
            scan = Scan(kin, scene, radius, pitch, SensorMount(tilt=-pitch))
            points = np.array([scan.point(float(a)) for a in angles])
            labels = [f"scan at {math.degrees(a):.0f} deg" for a in angles]
            try:
                moves(
                    ctx, State(arm.driver.read(), scene, None, None), points, pitch, labels, kin=kin
                )
            except TaskError as exc:
                first = first or exc
                continue
            return scan
    assert first is not None
    raise first
