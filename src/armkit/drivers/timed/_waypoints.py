"""A path (a straight line, a drawing) on the OWI-535: waypoints its timed motors can make.

The driver turns one joint at a time and a turn under the smallest reliable step
(``_short.smallest_step``: 1.25 x ``min_move_s`` of motor time, slip and coast
included, ~5-7 deg, 20-30 mm at the gripper) is made in two legs, past the target
and back. Streamed every few millimetres, a 20 mm line became 92 such runs: 29.8 s
of motor time, up to 30 mm off the line by the plan and 100-200 mm by the end on
the simulated unit (every run adds its scatter). So the path is not streamed:
every joint follows its own angle along the path in levels at least its smallest
step apart (spread evenly from the path's start to its end, so the last level is
the end), moving to the nearest level once the path is half a level past the one
it is on. A waypoint is sent whenever a joint changes level: one run per joint
and level, no back-and-forth. The same 20 mm line: 6 runs, 1.7 s (50 mm across
the base: 2 runs, 0.6 s, was 17.3 s; 100 mm: 27 runs, 6.8 s, was 183 s).

Each run still swings the tool by a whole step, so the path strays from the
ideal one; ``plan_path_runs`` works out by how much (the tool along every run the
driver will make, from its forecast) and refuses a path that would stray more
than ``PATH_TOLERANCE`` before anything moves. By the plan: 1.6 mm across the
base, 10-27 mm in the arm's plane (one joint at a time, each run at least a step,
cannot do better than ~15 mm there), median ~25 mm over random 20-100 mm lines,
a few up to 35-50 mm where a joint turning less than a step must go past and back. The driver (``TimedDriver.follow_path``)
and the script checker (``armkit.script``) both use it, so the check's time and
the run's agree.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ..._errors import UnreachableError
from ..._polyline import distance_to_polyline
from ...kinematics import fk
from ...model import ArmModel
from ._forecast import forecast_move
from ._timing import TimingModel

F64 = NDArray[np.float64]
PATH_TOLERANCE = 0.040  # [m] the most a planned path may stray from the ideal one: about one
# smallest step of the shoulder (~7 deg) at full reach (310 mm); see the module doc
RUN_MARGIN = 1.05  # each run at least this many times min_move_s (the driver: 1.0)
MIN_SHARE = 1.0  # a level spacing at least this share of the step
SWITCH = 0.55  # a joint moves to its nearest level once the path is this many levels away
STEP_POSES = 24  # poses along the path at which the smallest steps are worked out
SWEEP_SAMPLES = 9  # tool points per run checked against the path


@dataclass(frozen=True)
class PathRuns:
    """What the driver does for a path, worked out before it moves.

    Attributes:
        waypoints: the joint targets after the move onto the path's start [rad], (K, 4).
        seconds: how long all the runs take, the move onto the start included [s].
        q: the driver's estimate after them [rad], shape (4,).
        motor_s: motor-seconds used after them [s].
        deviation: how far the tool strays from the path along the runs [m] (the
            move onto the start not counted), by the driver's estimate.
        runs: how many motor runs follow the path.
    """

    waypoints: F64
    seconds: float
    q: F64
    motor_s: float
    deviation: float
    runs: int

    def describe(self) -> str:
        """``"5 runs through 4 waypoints, up to 24.7 mm off the path"``."""
        return (
            f"{self.runs} runs through {len(self.waypoints)} waypoints, "
            f"up to {self.deviation * 1000:.1f} mm off the path"
        )


def path_waypoints(timing: TimingModel, q_path: F64, motor_s: float = 0.0) -> F64:
    """The waypoints [rad], (K, 4), that follow the joint path ``q_path`` [rad], (N, 4),
    each joint in levels at least its smallest step apart (see the module doc); the
    last is the path's end."""
    q_path = np.asarray(q_path, dtype=np.float64)
    start, end = q_path[0], q_path[-1]
    spacing = _spacings(timing, q_path, motor_s)
    level = start.copy()
    out: list[F64] = []
    for x in q_path[1:]:
        due = np.abs(x - level) >= SWITCH * spacing
        if due.any():
            k = np.round((x - start) / spacing)
            level = np.where(due, start + k * spacing, level)
            out.append(level.copy())
    if not out or not np.allclose(out[-1], end, rtol=0.0, atol=1e-12):
        out.append(end.copy())
    return np.array(out)


def _spacings(timing: TimingModel, q_path: F64, motor_s: float) -> F64:
    """Each joint's level spacing [rad]: the largest turn along the path (in the way it
    turns there) that a run of ``RUN_MARGIN`` x ``min_move_s`` makes, so every level
    change is one run; stretched so a whole number of levels spans the joint's turn
    from start to end (the number nearest turn / step that keeps every level change a
    run)."""
    index = np.unique(np.linspace(0, len(q_path) - 1, STEP_POSES).round().astype(int))
    poses, ahead = q_path[index], np.sign(np.diff(q_path[index], axis=0))
    total = q_path[-1] - q_path[0]
    out = np.empty(q_path.shape[1])
    seconds = RUN_MARGIN * timing.min_move_s
    for j in range(q_path.shape[1]):
        ways = {int(d) for d in ahead[:, j] if d} or {1, -1}
        step = max(
            abs(timing.advance(q, j, d, seconds, motor_s) - float(q[j]))
            for q in poses
            for d in ways
        )
        step = max(step, 1e-6)
        levels = max(1, round(abs(float(total[j])) / step))
        spacing = abs(float(total[j])) / levels
        while levels > 1 and spacing < step * MIN_SHARE:
            levels -= 1
            spacing = abs(float(total[j])) / levels
        out[j] = spacing if spacing >= step * MIN_SHARE else step
    return out


def plan_path_runs(
    timing: TimingModel,
    model: ArmModel,
    q0: F64,
    motor_s: float,
    q_path: F64,
    points: F64,
    tolerance: float = PATH_TOLERANCE,
) -> PathRuns:
    """What ``TimedDriver.follow_path`` does from the estimate ``q0`` [rad] with ``motor_s``
    [s] used: a move onto the start of ``q_path`` [rad], (N, 4), then its waypoints, each
    forecast as the driver runs it; ``points`` [m], (N, 3), are the tool's ideal path.

    Raises:
        UnreachableError: the runs would stray more than ``tolerance`` [m] from the
            path (reason ``"discontinuous"``); nothing is planned to move.
        As ``forecast_move``: a joint limit, the table, a turn with no room for two legs.
    """
    onto = forecast_move(timing, model, q0, q_path[0], motor_s)
    waypoints = path_waypoints(timing, q_path, onto.motor_s)
    pose, used, seconds = onto.q, onto.motor_s, onto.seconds
    run, sweeps = onto.q.copy(), []
    for w in waypoints:
        ahead = forecast_move(timing, model, pose, w, used)
        for s in ahead.steps:  # the tool along each run, one joint turning
            sweep = np.repeat(run[None, :], SWEEP_SAMPLES, axis=0)
            sweep[:, s.joint] = np.linspace(run[s.joint], s.target, SWEEP_SAMPLES)
            sweeps.append(sweep)
            run[s.joint] = s.target
        pose, used, seconds = ahead.q, ahead.motor_s, seconds + ahead.seconds
    deviation = _deviation(model, sweeps, np.asarray(points, dtype=np.float64))
    if deviation > tolerance:
        raise UnreachableError(
            f"the {model.name}'s timed motors turn one joint at a time by at least their "
            f"smallest step, so this path would stray {deviation * 1000:.0f} mm from the "
            f"straight one (at most {tolerance * 1000:.0f}); use joint moves (move) instead",
            reason="discontinuous",
        )
    return PathRuns(waypoints, seconds, pose, used, deviation, len(sweeps))


def _deviation(model: ArmModel, sweeps: list[F64], points: F64) -> float:
    """The farthest [m] the tool gets from the polyline ``points``, (M, 3), along the
    joint ``sweeps`` [rad], each (SWEEP_SAMPLES, 4)."""
    if not sweeps or len(points) < 2:
        return 0.0
    tool = fk(model, np.concatenate(sweeps))[:, :3, 3]
    return float(distance_to_polyline(tool, points).max())
