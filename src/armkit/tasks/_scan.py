"""The scan of 002's search: the hand held low at a fixed radius and pitch, its
sensor looking level across the table, turned through an arc by the base. The
pose is chosen per arm (the first radius and pitch that reaches the whole arc and
clears everything), every scan pose checked before the first motion."""

from __future__ import annotations

import contextlib
import math
from collections.abc import Iterator
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from ..arm import Start
from ..kinematics import fk
from ..model import ArmModel
from ..scene import Scene
from ..sensing import RANGE, DistanceSensor, SensorMount, open_sensor, volts
from ._eye import Eye
from ._live import attached
from ._plan import TaskError
from ._state import Context, Options, State, moves, solve

if TYPE_CHECKING:
    from ..arm import Arm

F64 = NDArray[np.float64]
HEIGHT = 0.015  # [m] the beam's height above the table: across a 25 mm object
FINE = math.radians(1.0)  # 002: scan back in 1 deg steps
AVERAGE = 5  # readings averaged for the distance
RADII = (0.09, 0.11, 0.13)  # [m] tried in order (nearest first: objects stay beyond 4 cm)
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
    height: float = HEIGHT
    readings: list[tuple[float, float]] = field(default_factory=list)

    def point(self, angle: float, radius: float | None = None, dz: float = 0.0) -> F64:
        """The tool point at 002 servo angle ``angle`` [rad] (``radius`` [m] out, None:
        the scan's; ``dz`` [m] higher), scene frame [m], (3,)."""
        az, r = angle - AHEAD, self.radius if radius is None else radius
        base = np.array([r * math.cos(az), r * math.sin(az), self.height + dz])
        out: F64 = self.scene.to_scene(base + np.array([0.0, 0.0, self.scene.table_z]))
        return out

    def joints(self, angle: float, seed: F64, radius: float | None = None, dz: float = 0.0) -> F64:
        """The joints [rad] (dof,) of the scan pose at ``angle`` (see ``point``)."""
        base = self.scene.to_base(self.point(angle, radius, dz))
        return solve(
            self.kin, base, self.pitch, seed, "search", f"scan at {math.degrees(angle):.0f} deg"
        )

    def sweep(self, eye: Eye, angles: F64) -> list[tuple[float, float]]:
        """Turn to each of ``angles`` [rad] and read the sensor: [(angle, volts)]."""
        out = []
        for a in angles:
            q = self.joints(float(a), eye.q())
            out.append((float(a), eye.look(q, f"scan at {math.degrees(a):.0f} deg")))
        self.readings.extend(out)
        return out

    def object_at(self, seed: F64, angle: float, distance: float, size: float) -> F64:
        """The bottom centre [m] (3,) of a cube of ``size`` [m] whose near face the beam
        meets ``distance`` [m] out at ``angle`` [rad] (solved nearest joints ``seed``)."""
        q = self.joints(angle, seed)
        origin, d = self.mount.beam(self.scene.T_world_base @ fk(self.kin, q))
        level = np.array([d[0], d[1], 0.0]) / max(float(np.hypot(d[0], d[1])), 1e-9)
        centre = origin + distance * d + level * size / 2.0
        return np.array([centre[0], centre[1], self.scene.table_z])


def locate(
    eye: Eye, scan: Scan, start: float, stop: float, step: float
) -> tuple[float, float] | None:
    """002: scan from ``start`` to ``stop`` every ``step`` [rad] for a local maximum of
    the output, back in 1 deg steps over it, align with its middle and measure:
    (angle [rad], distance [m]), or None if nothing is within range."""
    eye.open()  # the jaws as the scan was planned
    coarse = scan.sweep(eye, np.arange(start, stop + step / 2, step) if stop > start
                        else np.arange(start, stop - step / 2, -step))  # fmt: skip
    floor = volts(RANGE[1])
    best = max(range(len(coarse)), key=lambda k: coarse[k][1])
    if coarse[best][1] < floor:
        return None
    background = float(np.median([v for _, v in coarse]))
    half = (coarse[best][1] + background) / 2.0
    lo, hi = best, best
    while lo > 0 and coarse[lo - 1][1] >= half:
        lo -= 1
    while hi < len(coarse) - 1 and coarse[hi + 1][1] >= half:
        hi += 1
    a, b = coarse[min(hi + 1, len(coarse) - 1)][0], coarse[max(lo - 1, 0)][0]
    n = max(2, round(abs(b - a) / FINE) + 1)
    fine = scan.sweep(eye, np.linspace(a, b, n))
    angle = _middle(fine, background)
    scan.sweep(eye, np.array([angle]))
    dist = [d for d in (eye.distance() for _ in range(AVERAGE)) if d is not None]
    if not dist:
        return None
    d = float(np.median(dist))
    return angle, d


def _middle(readings: list[tuple[float, float]], background: float) -> float:
    """The middle of the angles [rad] where the output is above half way from the
    ``background`` [V] to its peak: the object's direction (its nearest point is not,
    for a cube seen at a slant)."""
    top = max(v for _, v in readings)
    half = (top + background) / 2.0
    seen = [a for a, v in readings if v >= half]
    return (min(seen) + max(seen)) / 2.0


def plan_scan(
    arm: Arm | Start, scene: Scene, start: float, stop: float, step: float, height: float = HEIGHT
) -> Scan:
    """The first scan pose (RADII x PITCHES, the beam ``height`` [m] up) whose every coarse pose is reachable and
    whose moves through them are clear; nothing moves.

    Raises:
        TaskError: none is, naming the step of the first pose tried.
    """
    q0 = arm.q if isinstance(arm, Start) else arm.read()
    g = arm.model.gripper
    kin = arm.model.with_grip_width(g.width_max)
    n = max(1, round(abs(stop - start) / step))
    angles = np.linspace(start, stop, n + 1)
    ctx = Context(arm.model, Options(), "search")
    first: TaskError | None = None
    for radius in RADII:
        for pitch in PITCHES:
            scan = Scan(kin, scene, radius, pitch, SensorMount(tilt=-pitch), height=height)
            points = np.array([scan.point(float(a)) for a in angles])
            labels = [f"scan at {math.degrees(a):.0f} deg" for a in angles]
            try:
                moves(ctx, State(q0, scene, None, None), points, pitch, labels, kin=kin)
            except TaskError as exc:
                first = first or exc
                continue
            return scan
    assert first is not None
    raise first


@contextlib.contextmanager
def scan_sensor(
    arm: Arm, scan: Scan, channel: int, port: str | None, seed: int
) -> Iterator[DistanceSensor]:
    """The distance sensor for ``scan``: on a simulated arm with the scene attached, a
    simulated GP2D120 installed at the scan's mount first (noise seeded ``seed``); read
    through the SSC-32 or an ADC board (``port``; see ``sensing.open_sensor``)."""
    sim, physics = arm.sim, attached(arm)
    if sim is not None and physics is not None:
        sim.install_sensor(physics, scan.mount, channel=channel, seed=seed)
    lock = None if arm.world is None else arm.world.lock
    inputs = None if sim is None else sim.analog
    with open_sensor(
        arm.analog_inputs(), channel, port, inputs=inputs, lock=lock, arm=arm.model.name
    ) as sensor:
        yield sensor
