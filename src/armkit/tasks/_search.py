"""Seed 002's search: scan an arc with the distance sensor on the hand looking for a
local maximum of its output, scan back in fine steps to pinpoint it, align, measure
the distance, pick the object up and drop it in the container, go back to rest and
switch the servos off. Angles as 002's base servo: 90 deg is straight ahead, 30 is
60 deg to the right, 120 is 30 deg to the left (any arm)."""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from .._errors import InputError
from .._inputs import is_number, shown
from .._terminal import count
from ..arm import Start, plan_joints
from ..kinematics import fk
from ..model import ArmModel
from ..scene import Container, Cube, Scene, settle
from ..sensing import RANGE
from ._choose import pick_any
from ._eye import ArmEye, PlanEye
from ._jobs import plan_task
from ._live import TaskFailed, attached, live_scene, run_verified
from ._plan import Plan, TaskError, cube_text
from ._scan import Scan, locate, plan_scan, scan_sensor
from ._state import Context, State, down, grip

if TYPE_CHECKING:
    from ..arm import Arm

F64 = NDArray[np.float64]
OBJECT_SIZE = 0.025  # [m] 002's object when the scene has no cube to say
DROP_HEIGHT = 0.015  # [m] above the container's rim
DROP_PITCHES = tuple(math.radians(p) for p in (-90.0, -75.0, -60.0, -45.0, -30.0, 0.0))


@dataclass(frozen=True)
class SearchResult:
    """What the search found and did.

    Attributes:
        found: an object was seen within the sensor's range.
        angle: the base angle it was seen at, 002's servo convention [deg].
        distance: the sensor's distance to it there [mm].
        position: where its bottom face's centre is estimated, scene frame [mm], (3,).
        readings: (angle [deg], output [V]) of every reading, in order.
        plan: the pick-and-drop plan carried out, or None.
        servos_off: the motors were switched off at the end (False: the driver cannot).
        via: how the sensor was read.
        band: how far from the arm's base axis [mm] (near, far) the sensor sees along the
            arc: where it is held plus its 4..30 cm (an object nearer is inside its minimum).
    """

    found: bool
    angle: float | None
    distance: float | None
    position: F64 | None
    readings: tuple[tuple[float, float], ...]
    plan: Plan | None
    servos_off: bool
    via: str
    band: tuple[float, float] = (0.0, 0.0)

    def lines(self) -> list[str]:
        """The result for people (mm, deg)."""
        out = [f"sensor read through {self.via}; {count(len(self.readings), 'reading')}"]
        if not self.found or self.position is None or self.angle is None:
            near, far = (round(b) for b in self.band)
            return [*out, f"nothing found {near}..{far} mm from the base axis along the arc"]
        x, y, z = (float(v) for v in self.position)
        assert self.distance is not None
        out.append(
            f"found at {self.angle:.1f} deg, {self.distance:.1f} mm from "
            f"the sensor: ({x:.1f}, {y:.1f}, {z:.1f}) mm"
        )
        if self.plan is not None:
            out.append(f"picked it and dropped it: {self.plan.task}")
        out.append("motors off" if self.servos_off else "motors left holding (the driver cannot)")
        return out


def search(
    arm: Arm,
    scene: Scene,
    *,
    start: float = 30.0,
    stop: float = 120.0,
    step: float = 5.0,
    into: str | None = None,
    channel: int = 0,
    port: str | None = None,
    seed: int = 2,
) -> SearchResult:
    """002: scan from ``start`` to ``stop`` every ``step`` [deg] (002's servo angles),
    then back in 1 deg steps round the best reading, pick what is there up and drop it
    in the container ``into`` (None: the scene's only container), rest, servos off.
    The scan holds the hand 15 mm above the table, 90 to 130 mm from the base.

    ``channel``: the sensor's analog input; ``port``: an ADC board's port (arms without
    an SSC-32 on real hardware); ``seed``: the simulated sensor's noise.

    Raises:
        TaskError: the scan or the pick is unreachable or would collide (nothing moves
            for the scan; the arm stops after it for the pick).
        ValueError: bad angles or container.
    """
    start, stop, step = check_angles(start, stop, step)
    scene = live_scene(arm, scene, False, "search")
    bin_name = into or only_container(scene)
    scene.container(bin_name)
    scan = plan_scan(arm, scene, start, stop, step)
    with scan_sensor(arm, scan, channel, port, seed) as sensor:
        found = locate(ArmEye(arm, sensor), scan, start, stop, step)
        via = sensor.via
    if found is None:
        return _result(scan, None, None, None, _rest(arm), via)
    angle, dist = found
    position = scan.object_at(arm.read(), angle, dist, _size(attached_cubes(arm)))
    plan = _fetch(arm, scene, position, bin_name)
    run_verified(arm, plan, poses=False, allow=("dropped", "tipped"))
    _check_inside(arm, plan, scene.container(bin_name))
    return _result(scan, (angle, dist), position, plan, _rest(arm), via)


def _result(
    scan: Scan,
    found: tuple[float, float] | None,
    position: F64 | None,
    plan: Plan | None,
    servos_off: bool,
    via: str,
) -> SearchResult:
    """The search's result in mm and degrees from the scan's [rad, m]: ``found`` (angle,
    distance) where it saw the object at ``position`` (None: nothing seen)."""
    readings = tuple((math.degrees(a), v) for a, v in scan.readings)
    band = (1000.0 * (scan.radius + RANGE[0]), 1000.0 * (scan.radius + RANGE[1]))
    if found is None or position is None:
        return SearchResult(False, None, None, None, readings, None, servos_off, via, band)
    angle, dist = math.degrees(found[0]), 1000.0 * found[1]
    return SearchResult(True, angle, dist, position * 1000.0, readings, plan, servos_off, via, band)


def check_angles(start: float, stop: float, step: float) -> tuple[float, float, float]:
    """A scan's arc from ``start`` to ``stop`` every ``step`` [deg] (002's servo angles),
    checked (InputError otherwise), in radians."""
    values = (start, stop, step)
    numbers = all(is_number(v) and math.isfinite(v) for v in values)
    if (
        not numbers
        or not all(0.0 <= a <= 180.0 for a in (start, stop))
        or not 0 < step <= abs(stop - start)
    ):
        raise InputError(
            f"search scans from and to 0..180 deg (002's base servo, 90 straight ahead) with "
            f"0 < step <= |to - from|; got from {shown(start)} to {shown(stop)} step "
            f"{shown(step)} deg"
        )
    return math.radians(start), math.radians(stop), math.radians(step)


def only_container(scene: Scene) -> str:
    """The name of the scene's one container; InputError if it has none or several."""
    if len(scene.containers) != 1:
        names = ", ".join(c.name for c in scene.containers) or "none"
        raise InputError(f"search: say which container to drop into (into NAME); scene has {names}")
    return scene.containers[0].name


def attached_cubes(arm: Arm) -> tuple[Cube, ...]:
    """The cubes of the scene physics attached to ``arm``'s world (none on hardware)."""
    physics = attached(arm)
    return () if physics is None else physics.scene.cubes


def _size(cubes: tuple[Cube, ...]) -> float:
    """The object's size [m]: the scene's one cube's, else 002's object's."""
    return cubes[0].size if len(cubes) == 1 else OBJECT_SIZE


def plan_search(
    arm: Start,
    scene: Scene,
    *,
    start: float = 30.0,
    stop: float = 120.0,
    step: float = 5.0,
    into: str | None = None,
) -> Plan:
    """``search`` planned from ``arm`` with nothing moving: its scan from ``start`` to
    ``stop`` every ``step`` [deg] (002's servo angles), the sensor's readings what the
    scene puts along its beam (no noise; the hand 15 mm above the table, 90 to 130 mm
    from the base), then, if it finds the object, the pick and the drop into ``into``
    planned on where the readings put it, and home (what ``armkit check`` plans a
    search with; the run reads the real sensor and may find otherwise).

    Raises:
        TaskError: the scan or the pick is unreachable or would collide.
        ValueError: bad angles or container.
    """
    a, b, s = check_angles(start, stop, step)
    bin_name = into or only_container(scene)
    scene.container(bin_name)
    scan = plan_scan(arm, scene, a, b, s)
    eye = PlanEye(arm.then(scene=scene), scene, scan.kin, scan.mount)
    found = locate(eye, scan, a, b, s)
    plan = eye.plan
    if found is not None:
        position = scan.object_at(eye.q(), found[0], found[1], _size(scene.cubes))
        plan = plan.then(_fetch(plan.end, scene, position, bin_name))
    return plan.then(plan_joints(plan.end, arm.model.home, label="home"), task="search")


def _fetch(arm: Arm | Start, scene: Scene, position: F64, container: str) -> Plan:
    """The pick at the estimated ``position`` and the drop over ``container``, planned
    whole: the scene's nearest cube is planned where it was estimated (the truth is
    the simulator's)."""
    cubes = sorted(scene.cubes, key=lambda c: float(np.linalg.norm(c.position - position)))
    yaw = math.atan2(float(position[1]), float(position[0]))
    if cubes:
        est = Cube(cubes[0].name, cubes[0].size, position, yaw)
        planned = scene.with_cube(est)
    else:
        est = Cube("found", OBJECT_SIZE, position, yaw)
        planned = replace(scene, cubes=(est,))
    box = scene.container(container)

    def body(c: Context, s: State) -> State:
        s = pick_any(c, s, est.name, None)
        return _drop(c, s, box, est.size)

    return plan_task(arm, planned, f"search: drop {est.name} in {container}", body)


def _drop(ctx: Context, st: State, box: Container, size: float) -> State:
    """Carry the held cube over the middle of ``box`` (its lowest corner DROP_HEIGHT
    above the rim) at the first pitch that works, and open (002 drops it)."""
    point = box.position + np.array([0.0, 0.0, box.size[2] + size + DROP_HEIGHT])
    kin = ctx.model.with_grip_width(size)
    label = f"over {box.name}"
    first: TaskError | None = None
    for pitch in DROP_PITCHES:
        try:
            st = down(ctx, st, point, pitch, label, kin=kin, ignore=frozenset())
        except TaskError as exc:
            first = first or exc
            continue
        st = grip(ctx, st, ctx.model.gripper.width_max, f"drop it in {box.name}")
        return _let_go(st, kin)
    assert first is not None
    raise first


def _let_go(st: State, kin: ArmModel) -> State:
    """The held cube let go where the jaws hold it: it settles (``scene.settle``) and is
    held no more."""
    assert st.held is not None
    T = st.scene.T_world_base @ fk(kin, st.q) @ st.held.T_tool_object
    rest = settle(st.scene, st.held.cube, T)
    return replace(st, held=None, scene=replace(st.scene, cubes=(*st.scene.cubes, rest.cube)))


def _check_inside(arm: Arm, plan: Plan, box: Container) -> None:
    """On a simulated arm: TaskFailed unless the dropped cube lies inside ``box``."""
    physics = attached(arm)
    name = next((s.holding for s in plan.steps if s.holding), None)
    if physics is None or name is None:
        return
    cube = physics.cube(name)
    inside = np.abs(cube.center[:2] - box.position[:2]) <= np.array(box.size[:2]) / 2 - box.wall
    if not bool(np.all(inside)):
        raise TaskFailed(
            f"{plan.task}: {cube_text(cube)}, not inside {box.name}",
            step=plan.steps[-1].label, detail=cube_text(cube),
        )  # fmt: skip


def _rest(arm: Arm) -> bool:
    """Back to the model's home, then the motors off if the driver can (002's uM-PWM1)."""
    arm.home()
    return arm.relax()
