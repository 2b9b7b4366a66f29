"""Seed 003's reach: find a hand held out with the distance sensor (002's scan, the
beam at the hand's height), come towards it along the beam until the sensor reads
near, shake (up and down), and go back home."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from .._errors import InputError
from .._inputs import is_number, shown
from .._terminal import count
from ..arm import Plan, Start, plan_joints
from ..scene import Scene
from ._eye import ArmEye, Eye, PlanEye
from ._live import live_scene
from ._plan import TaskError
from ._scan import Scan, locate, plan_scan, scan_sensor
from ._search import check_angles

if TYPE_CHECKING:
    from ..arm import Arm

APPROACH_STEP = 0.02  # [m] at most this much nearer per step


@dataclass(frozen=True)
class ReachResult:
    """What the reach did.

    Attributes:
        found: a hand was seen.  angle: where [deg] (002's servo convention).
        distance: the sensor's distance at the end of the approach [mm].
        steps: approach steps taken.  shakes: up-and-down shakes done.  via: the sensor's line.
    """

    found: bool
    angle: float | None
    distance: float | None
    steps: int
    shakes: int
    via: str

    def lines(self) -> list[str]:
        """The result for people (mm, deg)."""
        if not self.found or self.angle is None or self.distance is None:
            return [f"sensor read through {self.via}", "no hand within 30 cm along the arc"]
        return [
            f"sensor read through {self.via}",
            f"hand at {self.angle:.1f} deg; came {count(self.steps, 'step')} nearer, "
            f"to {self.distance:.0f} mm; shook {count(self.shakes, 'time')}",
        ]


def reach(
    arm: Arm,
    scene: Scene,
    *,
    height: float = 110.0,
    near: float = 60.0,
    shakes: int = 3,
    amplitude: float = 15.0,
    start: float = 30.0,
    stop: float = 120.0,
    step: float = 5.0,
    channel: int = 0,
    port: str | None = None,
    seed: int = 3,
) -> ReachResult:
    """003: scan at ``height`` [mm] (0..500) for a hand along the arc from ``start`` to
    ``stop`` every ``step`` [deg] (002's servo angles, as ``search``), approach until the
    sensor reads ``near`` [mm] (40..300), shake ``shakes`` times by ``amplitude`` [mm] up
    and down, go home.

    Raises:
        TaskError: the scan is unreachable or would collide (nothing moves), or the
            hand is out of reach (the arm stops where it got to and says how far).
        ValueError: a bad argument.
    """
    arc = check_angles(start, stop, step)
    height, near, amplitude = _check(height, near, shakes, amplitude)
    scene = live_scene(arm, scene, False, "reach")
    scan = plan_scan(arm, scene, *arc, height)
    with scan_sensor(arm, scan, channel, port, seed) as sensor:
        done = _reach(ArmEye(arm, sensor), scan, arc, near, (shakes, amplitude))
        via = sensor.via
    arm.home()
    if done is None:
        return ReachResult(False, None, None, 0, 0, via)
    angle, distance, steps = done
    return ReachResult(True, math.degrees(angle), 1000.0 * distance, steps, shakes, via)


def plan_reach(
    arm: Start,
    scene: Scene,
    *,
    height: float = 110.0,
    near: float = 60.0,
    shakes: int = 3,
    amplitude: float = 15.0,
    start: float = 30.0,
    stop: float = 120.0,
    step: float = 5.0,
) -> Plan:
    """``reach`` planned from ``arm`` with nothing moving, its arguments in mm and
    degrees as ``reach``'s: the same scan, approach and shakes, the sensor's readings
    what the scene (its hand) puts along the beam (no noise), then home.

    Raises:
        TaskError: the scan is unreachable or would collide, or the hand is out of reach.
        ValueError: a bad argument.
    """
    arc = check_angles(start, stop, step)
    h, n, amp = _check(height, near, shakes, amplitude)
    scan = plan_scan(arm, scene, *arc, h)
    eye = PlanEye(arm.then(scene=scene), scene, scan.kin, scan.mount)
    _reach(eye, scan, arc, n, (shakes, amp))
    home = plan_joints(eye.plan.end, arm.model.home, label="home")
    return eye.plan.then(home, task="reach")


def _reach(
    eye: Eye, scan: Scan, arc: tuple[float, float, float], near: float, shake: tuple[int, float]
) -> tuple[float, float, int] | None:
    """003 through ``eye``: find the hand on ``arc`` (start, stop, step [rad]), come
    ``near`` [m], shake (times, amplitude [m]); (angle [rad], distance [m], steps) or
    None if no hand was found."""
    found = locate(eye, scan, *arc)
    if found is None:
        return None
    angle, d = found
    radius, d, steps = _approach(eye, scan, angle, d, near)
    _shake(eye, scan, angle, radius, *shake)
    return angle, d, steps


def _check(height: float, near: float, shakes: int, amplitude: float) -> tuple[float, float, float]:
    """The reach's distances [mm] checked, in metres (InputError otherwise)."""
    numbers = all(is_number(v) and math.isfinite(v) for v in (height, near, amplitude))
    if not (numbers and isinstance(shakes, int | np.integer) and not isinstance(shakes, bool)):
        raise InputError(
            f"reach needs height, near and amplitude numbers [mm] and shakes a whole number; "
            f"got height {shown(height)}, near {shown(near)}, shakes {shown(shakes)}, "
            f"amplitude {shown(amplitude)}"
        )
    if not (0 < height <= 500 and 40 <= near <= 300 and 0 <= shakes <= 20 and 0 < amplitude <= 50):
        raise InputError(
            f"reach needs height 0..500 mm, near 40..300 mm, shakes 0..20, amplitude 0..50 mm; "
            f"got height {height:g} mm, near {near:g} mm, shakes {shakes}, amplitude {amplitude:g} mm"
        )
    return height / 1000.0, near / 1000.0, amplitude / 1000.0


def _approach(
    eye: Eye, scan: Scan, angle: float, d: float, near: float
) -> tuple[float, float, int]:
    """Step along the beam until the sensor reads ``near`` [m]: (radius [m], last
    distance [m], steps)."""
    radius, steps = scan.radius, 0
    while d > near + 1e-3:
        radius += min(APPROACH_STEP, d - near)
        try:
            q = scan.joints(angle, eye.q(), radius)
        except TaskError:
            raise TaskError(
                f"reach: the hand is {d * 1000:.0f} mm away and the arm can come no nearer",
                step=f"approach step {steps + 1}",
            ) from None
        eye.look(q, f"approach step {steps + 1}")
        steps += 1
        now = eye.distance()
        if now is None:
            break
        d = now
    return radius, d, steps


def _shake(eye: Eye, scan: Scan, angle: float, radius: float, shakes: int, amp: float) -> None:
    """Up ``amp`` [m], down ``amp``, ``shakes`` times, then level again."""
    seed = eye.q()
    poses = [scan.joints(angle, seed, radius, dz) for dz in (amp, -amp, 0.0)]
    for k in range(shakes):
        for q, way in zip(poses, ("up", "down", "level"), strict=True):
            eye.move(q, f"shake {k + 1}: {way}")
