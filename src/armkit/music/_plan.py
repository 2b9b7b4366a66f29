"""Plan a performance: every strike scheduled backwards from its note time.

For each note: the stroke from the hover pose is predicted (the predictor is the
servos' own motion model), the time from its start to the contact found, and the
stroke started that long (plus the bar's latency) before the note. The move to
the hover pose starts as soon as the arm is free after the previous rebound; a
note the arm cannot reach in time even at the lowest hover is a Problem with
the time it has and the time it would need. Times are performance time [s]:
0 is the first command, a note sounds at ``onset + offset``.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field, replace

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._errors import InputError, UnreachableError
from .._inputs import array, joints, shown, tolerance
from ..model import ArmModel
from ._layout import Bars, DrumLike, Instrument, StrikeSpot, map_notes
from ._listen import Surface, height_over, surfaces
from ._loop import Servos, lagged_contact
from ._onsets import LatencyTable
from ._performance import Move, Performance, Problem, Strike
from ._predict import JointProfile, Predictor, Rebound, rebound_of
from ._score import Score, tempo_factor
from ._strike import StrikeParams, StrikePoses, contact, strike_poses, tip_path

F64 = NDArray[np.float64]


@dataclass
class _Cursor:
    """Where the planner is: the arm's pose and when it is free [s, score time]."""

    q: F64
    free: float
    stage: _Stage
    moves: list[Move] = field(default_factory=list)
    strikes: list[Strike] = field(default_factory=list)
    problems: list[Problem] = field(default_factory=list)
    previous: float | None = None
    rebound: _Rebounded | None = None  # the last rebound


@dataclass(frozen=True)
class _Stage:
    """The struck surfaces (scene frame [m]) and the arm's base in the scene frame,
    shape (4, 4): what the stick must clear while it travels."""

    surfaces: tuple[Surface, ...]
    T_world_base: F64

    def clearance(self, arm: ArmModel, travel: JointProfile, margin: float) -> float:
        """Smallest height [m] of the stick's tip above a bar or drum it passes over
        (within ``margin`` [m] of its edge) along ``travel``; inf over none."""
        T = self.T_world_base
        return height_over(self.surfaces, tip_path(arm, travel) @ T[:3, :3].T + T[:3, 3], margin)


@dataclass(frozen=True)
class _Rebounded:
    """The last rebound: sent at ``t`` [s] from ``q`` [rad] on ``key``'s bar, its stroke
    between the poses ``ends`` [rad], shape (2, dof)."""

    t: float
    q: F64
    ends: F64
    key: tuple[str, int]


def plan_performance(
    score: Score,
    layout: Sequence[Instrument],
    model: ArmModel,
    predictor: Predictor,
    *,
    tool_length: float | None = None,
    params: StrikeParams | None = None,
    latency: LatencyTable | None = None,
    start: ArrayLike | None = None,
    T_world_base: ArrayLike | None = None,
    tempo: float = 1.0,
    rebound: Rebound | None = None,
    loop: float = 0.0,
) -> Performance:
    """Plan every strike of ``score`` on ``layout``.

    Args:
        score: the piece; ``tempo`` scales it (2.0 = twice as fast).
        layout: xylophones and drums (scene frame [m]); RangeError if a note has none.
        model: the arm; ``tool_length`` [m] replaces its tool (the stick as held).
        predictor: the servos' motion model (``time_based_predictor(model)`` ...),
            made for the same arm and tool.
        params: how to strike; latency: per-bar delays [s] from a calibration run.
        start: the arm's pose when the performance starts [rad], default home.
        T_world_base: the arm's base in the scene frame, shape (4, 4), default identity.
        rebound: how a rebound moves (``timed_predictor(model)`` on Dynamixel servos: sent
            with its duration, no slower ramp than the time allows), default ``predictor``'s.
        loop: the servos' position loop as a first-order lag [s] (hobby servos:
            ``SERVO_LAG``), 0: a pure delay; a stroke starting from rest is then timed
            by how far the loop has built up its lag at the contact.

    Returns:
        The Performance; ``check_performance`` refuses it if any note is infeasible
        (its ``replan(tempo)`` is this plan at another tempo).

    Raises:
        InputError: an argument of the wrong kind (named), before anything is planned.
        RangeError: a note no instrument of ``layout`` plays.
    """
    _check_arguments(score, layout, model, predictor, rebound, params, latency)
    factor = tempo_factor(tempo)
    arm = (
        model
        if tool_length is None
        else model.with_tool_length(tolerance(tool_length, "tool_length"))
    )
    p = params or StrikeParams()
    delays = latency or LatencyTable()
    T = np.eye(4) if T_world_base is None else array(T_world_base, "T_world_base", ((4, 4),), "m")
    T_base_world = np.linalg.inv(T)
    begin = arm.home if start is None else joints(start, arm.dof, "start", batch=False)
    cursor = _Cursor(begin, -np.inf, _Stage(surfaces(layout), T))
    servos = Servos(predictor, rebound or rebound_of(predictor), loop)
    for target in map_notes(score.at_tempo(factor) if factor != 1.0 else score, layout):
        point = (T_base_world @ np.append(target.point, 1.0))[:3]
        _plan_note(arm, servos, p, target, point, delays.of(target.key), cursor)

    def replan(at: float) -> Performance:
        return plan_performance(
            score, layout, model, predictor, tool_length=tool_length, params=params,
            latency=latency, start=start, T_world_base=T_world_base, tempo=at, rebound=rebound,
            loop=loop,
        )  # fmt: skip

    return replace(_shifted(cursor, arm, score.source, factor), replan=replan)


def _check_arguments(
    score: object,
    layout: object,
    model: object,
    predictor: object,
    rebound: object,
    params: object,
    latency: object,
) -> None:
    """InputError naming the first argument of ``plan_performance`` of the wrong kind."""
    if not isinstance(score, Score):
        raise InputError(
            f"score must be a Score (load_score, parse_notelist, ...), got {shown(score)}"
        )
    if not isinstance(layout, (tuple, list)) or not all(
        isinstance(i, (Bars, DrumLike)) for i in layout
    ):
        one = (
            " (one instrument: write (instrument,))" if isinstance(layout, (Bars, DrumLike)) else ""
        )
        raise InputError(
            "layout must be a tuple or list of xylophones and drums (armkit.scene's Xylophone "
            f"and Drum, a scene's instruments){one}, got {shown(layout)}"
        )
    if not isinstance(model, ArmModel):
        raise InputError(f"model must be an ArmModel (armkit.load_model), got {shown(model)}")
    if not callable(predictor):
        raise InputError(
            "predictor must be the servos' motion model, a function (q0, q1, speed) -> "
            f"JointProfile (time_based_predictor(model), ...), got {shown(predictor)}"
        )
    if rebound is not None and not callable(rebound):
        raise InputError(
            "rebound must be None or a function (q0, q1, speed, around) -> JointProfile "
            f"(timed_predictor(model)), got {shown(rebound)}"
        )
    if params is not None and not isinstance(params, StrikeParams):
        raise InputError(f"params must be None or a StrikeParams, got {shown(params)}")
    if latency is not None and not isinstance(latency, LatencyTable):
        raise InputError(f"latency must be None or a LatencyTable, got {shown(latency)}")


@dataclass(frozen=True)
class _Option:
    """One way to play a note: its poses, predicted stroke, contact and travel."""

    poses: StrikePoses
    down: JointProfile
    hit: float  # contact time from the stroke's start [s]
    speed: float  # tip speed at contact [m/s]
    travel: JointProfile  # to the hover pose (from the last contact if ``again``)
    stroke_start: float  # score time [s]
    ready: float  # earliest stroke start the arm can make [s]
    again: bool  # the same bar as the last note: its rebound goes straight to this hover

    @property
    def fits(self) -> bool:
        return self.ready <= self.stroke_start + 1e-9


def _plan_note(
    arm: ArmModel,
    servos: Servos,
    p: StrikeParams,
    target: StrikeSpot,
    point: F64,
    lag: float,
    cursor: _Cursor,
) -> None:
    """Schedule one note after the previous one, at the highest hover that fits."""
    best, why = None, "no stroke reaches the top"
    for height in p.heights(target.note.velocity):
        try:
            depth = p.aim(target.note.velocity, float(height), float(point[2]) - arm.table_z)
            poses = strike_poses(arm, point, float(height), depth, p.pitch, cursor.q)
        except UnreachableError as exc:
            why = str(exc)
            continue
        option = _option(arm, servos, p, target, float(point[2]), lag, cursor, poses)
        best = option or best
        if best is not None and best.fits:
            break
    if best is None:
        cursor.problems.append(Problem(target.note, "unreachable", detail=why))
    else:
        _schedule(arm, servos, p, target, lag, cursor, best)


def _option(
    arm: ArmModel,
    servos: Servos,
    p: StrikeParams,
    target: StrikeSpot,
    top: float,
    lag: float,
    cursor: _Cursor,
    poses: StrikePoses,
) -> _Option | None:
    """The timing of a strike from ``poses``, or None if its stroke never reaches ``top``.
    On the bar of the last note, the last rebound goes straight to the new hover."""
    last = cursor.rebound
    if last is not None and last.key == target.key:
        since, again = last.t, True
        travel = servos.rebound(last.q, poses.hover, p.travel_speed, last.ends)
    else:
        since, again = cursor.free, False
        travel = servos.move(cursor.q, poses.hover, p.travel_speed)
    down = servos.move(end_of(travel), poses.through, p.stroke_speed(target.note.velocity))
    hit = contact(arm, down, top)
    if hit is None:
        return None
    stroke_start = target.note.onset - lag - hit[0]
    if servos.loop > 0.0:  # behind a first-order loop: where its lag has built up to
        lead = p.settle + travel.duration  # a first travel is sent this long before the stroke
        move = (since, lead, again, travel)
        stroke_start = _behind_loop(arm, servos, cursor, move, down, top, lag, target)
    ready = since + travel.duration + p.settle
    return _Option(poses, down, hit[0], hit[1], travel, stroke_start, ready, again)


def _schedule(
    arm: ArmModel,
    servos: Servos,
    p: StrikeParams,
    target: StrikeSpot,
    lag: float,
    cursor: _Cursor,
    o: _Option,
) -> None:
    """Append the travel, down stroke and rebound of ``o`` and move the cursor on."""
    note, index = target.note, len(cursor.strikes)
    if not o.fits and cursor.previous is not None:
        needed = o.ready + o.hit + lag - cursor.previous
        cursor.problems.append(Problem(note, "too soon", note.onset - cursor.previous, needed))
    if o.again:  # the last rebound goes straight to this note's hover
        last = cursor.moves.pop()
        cursor.moves.append(
            Move(last.t, o.poses.hover, o.travel, last.speed, last.kind, last.strike, True)
        )
    elif not np.isfinite(cursor.free):
        send = o.stroke_start - p.settle - o.travel.duration
        cursor.moves.append(
            Move(send, o.poses.hover, o.travel, p.travel_speed, "travel", index, True)
        )
    elif o.travel.duration > 0:
        cursor.moves.append(
            Move(cursor.free, o.poses.hover, o.travel, p.travel_speed, "travel", index, True)
        )
        if cursor.stage.clearance(arm, o.travel, p.clearance) < p.clearance:
            detail = "the stick passes too close to a bar or drum on the way; raise the hover"
            cursor.problems.append(Problem(note, "low travel", detail=detail))
    speed = p.stroke_speed(note.velocity)
    cursor.moves.append(Move(o.stroke_start, o.poses.through, o.down, speed, "down", index, True))
    _rebound(servos, p, note.onset - lag + p.rebound_delay, target, o, cursor)
    cursor.strikes.append(Strike(target, note.onset, o.poses.height, o.poses, o.speed, lag))
    cursor.previous = note.onset


def _rebound(
    servos: Servos, p: StrikeParams, at: float, target: StrikeSpot, o: _Option, cursor: _Cursor
) -> None:
    """Append the rebound of ``o``'s stroke, sent at ``at`` [s], back to its hover (a
    timed move: see ``timed_predictor``), and move the cursor to its end."""
    q_now = o.down.sample(np.array([at - o.stroke_start]))[0][0]
    ends = np.vstack([end_of(o.travel), end_of(o.down)])
    rebound = servos.rebound(q_now, o.poses.hover, p.travel_speed, ends)
    index = len(cursor.strikes)
    cursor.moves.append(Move(at, o.poses.hover, rebound, p.travel_speed, "rebound", index, True))
    cursor.q, cursor.free = end_of(rebound), at + rebound.duration
    cursor.rebound = _Rebounded(at, q_now, ends, target.key)


def _behind_loop(
    arm: ArmModel,
    servos: Servos,
    cursor: _Cursor,
    travel: tuple[float, float, bool, JointProfile],
    down: JointProfile,
    top: float,
    lag: float,
    target: StrikeSpot,
) -> float:
    """The stroke's start [s] at which the head, behind the servos' first-order loop
    (``Servos.loop``, the commands so far, the travel and the stroke), touches the top
    ``lag - loop`` [s] (the latency table's rest) before the note: from the pure-delay
    start, three corrections. ``travel``: (send time [s] or -inf for the first note's,
    sent ``lead`` [s] before the stroke; ``again``: it replaces the last rebound; its
    profile)."""
    since, lead, again, profile = travel
    onset = target.note.onset - (lag - servos.loop)
    before = [(m.t, m.profile) for m in cursor.moves]
    if again:
        before = before[:-1]  # the same bar again: the travel replaces the last rebound
    start = target.note.onset - lag - contact_time(arm, down, top)
    for _ in range(3):
        sent = since if np.isfinite(since) else start - lead
        commands = [*before, (sent, profile), (start, down)]
        touched = lagged_contact(arm, commands, top + 0.0, start, servos.loop)
        if touched is None:
            break
        start += onset - touched
    return start


def contact_time(arm: ArmModel, down: JointProfile, top: float) -> float:
    """When [s] the stroke's own command crosses ``top`` (0 if it never does)."""
    hit = contact(arm, down, top)
    return 0.0 if hit is None else hit[0]


def end_of(profile: JointProfile) -> F64:
    """Where ``profile`` ends [rad], shape (dof,): the goal as the servos resolve it."""
    end: F64 = profile.sample(np.array([profile.duration]))[0][0]
    return end


def _shifted(cursor: _Cursor, arm: ArmModel, source: str, tempo: float) -> Performance:
    """Shift score time so that the first command is sent at 0."""
    offset = max(0.0, -min((m.t for m in cursor.moves), default=0.0))
    moves = tuple(sorted((_later(m, offset) for m in cursor.moves), key=lambda m: m.t))
    strikes = tuple(
        Strike(s.target, s.time + offset, s.hover, s.poses, s.speed, s.latency)
        for s in cursor.strikes
    )
    return Performance(strikes, moves, tuple(cursor.problems), offset, arm, source, tempo)


def _later(move: Move, offset: float) -> Move:
    return replace(move, t=move.t + offset)
