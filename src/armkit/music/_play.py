"""The ``play`` job: a score played on the scene's instruments by an ``Arm``.

The whole piece is planned and checked before anything moves (every note on a
bar or drum, every pose in reach and clear of the table and the scene, every
note reachable in time); then the commands are sent at their planned times on
the arm's clock. On Dynamixel servos each move is one time-based profile at
the move's speed (the driver sets profile velocity and acceleration per
stroke); on hobby servos each move is one group move lasting exactly the
predicted time. In the simulator a ``Listener`` on the arm's World hears every
contact, so what was played can be compared with the plan.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from .._errors import InputError, UnreachableError
from .._inputs import is_number, shown
from ..arm import Plan, Start, Step, plan_steps
from ..model import ArmModel
from ..scene import HeldTool, move_refusal
from ._chords import check_chords, one_line
from ._layout import Instrument, RangeError, map_notes
from ._listen import Listener
from ._load import load_score
from ._onsets import Contact, LatencyTable, OnsetStats, onset_stats
from ._performance import Move, Performance, check_performance
from ._plan import plan_performance
from ._score import Score, tempo_factor
from ._servos import SERVO_LAG, predictors, servo_kind
from ._strike import StrikeParams

if TYPE_CHECKING:
    from ..arm import Arm
    from ..scene import Scene
    from ._heard import MujocoListener

F64 = NDArray[np.float64]
MALLET = "mallet"  # the scene's pen that is the mallet (its tip_offset lengthens the tool)
TAIL_S = 0.3  # time listened after the last command ends [s]


@dataclass(frozen=True)
class Played:
    """A piece as planned and as played.

    Attributes:
        performance: the plan (strike times [s] from the first command).
        contacts: the contacts heard in the simulator [s, performance time]; empty
            on hardware (nothing listens) or in a dry run.
        dwell: time the mallet stayed below the top, per contact [s].
        stats: onset errors of ``contacts`` against the plan (None if not listened).
        latency: the latency table it was planned with (``LatencyTable.from_run(
            planned, contacts, latency)`` is the next calibration).
    """

    performance: Performance
    contacts: tuple[Contact, ...] = ()
    dwell: tuple[float, ...] = ()
    stats: OnsetStats | None = None
    latency: LatencyTable = field(default_factory=LatencyTable)


def play(
    arm: Arm,
    scene: Scene,
    file: str | Path | Score,
    on: str | None = None,
    tempo: float | None = None,
    transpose: int | None = None,
    *,
    dry_run: bool = False,
    latency: LatencyTable | None = None,
    params: StrikeParams | None = None,
    hover: float | None = None,
    chords: str = "top",
) -> Played:
    """Play the score ``file`` (MIDI, RTTTL or a note list) on the scene's instruments
    (where they stand in the scene, in millimetres and degrees as every scene file gives
    them; the arm planned from its joints now, in degrees as ``Arm`` reports them).

    Args:
        arm: the arm, holding the mallet (the scene's pen ``mallet``, if any, says how
            much longer it makes the tool, in mm in the scene file).
        scene: the instruments (``armkit.scene``), in the scene frame.
        file: the score (a file, or a Score).  on: play on this instrument only.
        tempo: speed factor, ``MIN_TEMPO..MAX_TEMPO`` (0.8 = 80 %, slower), default 1.
        transpose: semitones to move pitched notes by, default 0.
        dry_run: plan and check only; nothing moves.
        latency: per-bar delays [s] from a calibration run (default: the servos' lag,
            ``SERVO_LAG``).  params: how to strike (default: rebound just after the
            lagging contact).
        hover: the mallet head's height above a bar before the loudest stroke [mm]
            (softer notes start lower, down to 10 mm or ``hover``), default 30.
        chords: notes written together: ``"top"`` keeps the highest (a warning says
            what was dropped), ``"arpeggio"`` plays them one after another, ``"refuse"``.

    Raises:
        ScoreError, RangeError, PerformanceError, UnreachableError, InputError: the
            piece cannot be played as asked; nothing has moved.
    """
    table = latency or LatencyTable(default=SERVO_LAG[servo_kind(arm.start())])
    performance = prepare(
        arm, scene, file, on, tempo, transpose, table, params, hover=hover, chords=chords
    )
    if dry_run:
        return Played(performance, latency=table)
    return replace(perform(arm, scene, performance), latency=table)


def prepare(
    arm: Arm,
    scene: Scene,
    file: str | Path | Score,
    on: str | None = None,
    tempo: float | None = None,
    transpose: int | None = None,
    latency: LatencyTable | None = None,
    params: StrikeParams | None = None,
    *,
    hover: float | None = None,
    chords: str = "top",
) -> Performance:
    """Plan and check the whole piece (see ``play``: the instruments where the scene puts
    them in millimetres and degrees, ``hover`` [mm]) from where the arm is: ``plan_play``
    from ``arm.start()``, its model, its servos and its joints now; the Performance to send."""
    check_tempo(tempo)
    check_transpose(transpose)
    instruments(scene, on)
    return plan_play(
        arm.start(), scene, file, on, tempo, transpose,
        latency=latency, params=params, hover=hover, chords=chords,
    )  # fmt: skip


def plan_play(
    model: ArmModel | Start,
    scene: Scene,
    file: str | Path | Score,
    on: str | None = None,
    tempo: float | None = None,
    transpose: int | None = None,
    *,
    servos: str | None = None,
    latency: LatencyTable | None = None,
    params: StrikeParams | None = None,
    hover: float | None = None,
    chords: str = "top",
    script: bool = False,
) -> Performance:
    """The ``play`` job planned and checked whole on an arm known by its model alone:
    what ``play`` refuses before it moves, refused the same way (``armkit check`` plans a
    script's ``play`` so). Nothing moves; no arm is needed. The instruments stand where
    the scene puts them (millimetres and degrees, as every scene file gives them).

    Args:
        model: the arm's model at home (the scene's mallet lengthens its tool), or a
            ``Start`` (``armkit.arm``, as ``Arm.start()`` gives it): its model, its joints
            when the piece starts and its driver's servos.
        servos: ``"dynamixel"`` or ``"hobby"`` (default: the Start's driver's, else the
            model's own driver's).
        hover: as ``play``, in millimetres.
        script: errors say a tempo and a transposition as a script writes them
            (``tempo 46%``, ``transpose 12``) rather than ``--tempo 46``.
        The rest as ``play``.

    Raises:
        ScoreError, RangeError, PerformanceError (every late note, and the fastest tempo
            the planner plays the piece at), UnreachableError, InputError.
    """
    start = model if isinstance(model, Start) else Start(model, model.home)
    servos = servos or servo_kind(start)
    model = start.model
    factor = check_tempo(tempo, script=script)
    score, layout = score_on(scene, file, on, transpose, chords=chords, script=script)
    mallet = mallet_model(model, scene)
    predictor, rebound, lag, lead = predictors(servos, mallet)
    perf = plan_performance(
        score, layout, mallet, predictor,
        params=strike_params(params or StrikeParams(rebound_delay=lag - lead), hover),
        latency=latency or LatencyTable(default=lag), start=start.q,
        T_world_base=scene.T_world_base, tempo=factor, rebound=rebound,
        loop=lag if servos == "hobby" else 0.0,
    )  # fmt: skip
    check_performance(perf, lambda p: collision(p, scene, start.q) is None, script=script)
    hit = collision(perf, scene, start.q)
    if hit is not None:
        raise hit
    return perf


def strike_params(params: StrikeParams, hover: float | None) -> StrikeParams:
    """``params`` with the loudest stroke's hover ``hover`` [mm] (None: as they are);
    InputError outside 2..200 mm."""
    if hover is None:
        return params
    if not (is_number(hover) and 2.0 <= hover <= 200.0):
        raise InputError(f"hover must be 2..200 mm above the bar, got {shown(hover)}")
    h = float(hover) / 1000.0
    return replace(params, hover=h, min_hover=min(params.min_hover, h))


def score_on(
    scene: Scene,
    file: str | Path | Score,
    on: str | None = None,
    transpose: int | None = None,
    *,
    chords: str = "top",
    script: bool = False,
) -> tuple[Score, Sequence[Instrument]]:
    """The score, transposed, one line (``chords``: see ``one_line``), and the instruments
    it is played on; RangeError if a note is on none of them (with a transposition in all
    that fits, as ``--transpose N``, or with ``script`` as ``transpose N``)."""
    shift = check_transpose(transpose)
    layout = instruments(scene, on)
    check_chords(chords)
    score = file.transposed(shift) if isinstance(file, Score) else load_score(file, shift)
    score = one_line(score, chords)
    try:
        map_notes(score, layout)
    except RangeError as err:
        raise _in_all(err, shift, script) from None
    return score, layout


def _in_all(err: RangeError, shift: int, script: bool) -> RangeError:
    """``err`` of a score already moved by ``shift`` semitones, its hint the total (none
    at all: as written), written as ``--transpose N`` or, in a script, ``transpose N``."""
    if err.transpose is None or not (shift or script):
        return err
    told, total = err.transpose, shift + err.transpose
    option = "transpose" if script else "--transpose"
    if total == 0:
        hint = "as written every note fits: leave the transposition out"
    elif shift:
        hint = f"transpose by {total} semitones in all ({option} {total})"
    else:
        hint = f"transpose by {total} semitones ({option} {total})"
    message = str(err).replace(f"transpose by {told} semitones (--transpose {told})", hint)
    return RangeError(message, err.notes, total)


def check_tempo(tempo: float | None, *, script: bool = False) -> float:
    """The tempo factor (None: 1.0), ``MIN_TEMPO..MAX_TEMPO``; else InputError showing
    the tempo as given (with ``script``, in %: a script's ``tempo 45%``)."""
    return 1.0 if tempo is None else tempo_factor(tempo, percent=script)


def check_transpose(transpose: int | None) -> int:
    """The transposition [semitones] (None: 0), a whole number within +-48; else InputError."""
    if transpose is None:
        return 0
    if isinstance(transpose, bool) or not isinstance(transpose, int) or abs(transpose) > 48:
        raise InputError(
            f"transpose must be a whole number of semitones -48..48, got {shown(transpose)}"
        )
    return transpose


def instruments(scene: Scene, on: str | None) -> Sequence[Instrument]:
    """The scene's instruments, or only the one called ``on``."""
    names = [i.name for i in scene.instruments]
    if not names:
        raise InputError(
            f"scene {scene.name!r} has no xylophone or drum; use a scene with instruments "
            "(--scene xylophone)"
        )
    if on is None:
        return scene.instruments
    if on not in names:
        raise InputError(
            f"scene {scene.name!r} has no instrument {on!r}; it has {', '.join(names)}"
        )
    return tuple(i for i in scene.instruments if i.name == on)


def mallet_model(model: ArmModel, scene: Scene) -> ArmModel:
    """``model`` with the mallet as its tool: longer by the scene's ``mallet`` pen's
    ``tip_offset`` [m] (the tool as it is if the scene has no mallet)."""
    extra = next((p.tip_offset for p in scene.pens if p.name == MALLET), 0.0)
    return model.with_tool_length(model.tool_length + extra) if extra else model


def mallet_held(start: Start, scene: Scene) -> HeldTool | None:
    """The scene's mallet as the arm at ``start`` holds it while it plays (its head the
    tool point, the jaws at their opening), or None: the scene has no mallet."""
    if not any(p.name == MALLET for p in scene.pens):
        return None
    width = start.opening if start.opening is not None else start.model.gripper.width_min
    return HeldTool(MALLET, mallet_model(start.model, scene).tool_length, width)


def collision(perf: Performance, scene: Scene, q0: F64) -> UnreachableError | None:
    """Why the piece is refused on clearance, naming the note, or None: a pose of it, or
    the way to it from the one before (from ``q0`` [rad] for the first), putting a link
    into the table or a scene object (``scene.move_refusal``, the rule of every move;
    instruments are no obstacle: the mallet strikes through their tops)."""
    before = q0
    for move in perf.moves:
        hit = move_refusal(perf.model, before, move.q[None, :], scene)
        if hit is not None:
            note = perf.strikes[move.strike].target.note
            return UnreachableError(
                f"{note.name} at {note.onset:.3f} s, the {move.kind} pose: {hit}; or move "
                "the instrument",
                reason=hit.reason,
            )
        before = move.q
    return None


def performance_plan(start: Start, perf: Performance, scene: Scene) -> Plan:
    """``perf`` (the strikes ``plan_play`` planned where the scene puts the instruments, in
    millimetres and degrees) as a plan from ``start`` (checked as ``plan_play`` checks it): every move
    sent at its time without waiting, the servos' own ramps doing the rest (hobby servos
    and rebounds: each move lasting its predicted time; else at its speed), then
    ``TAIL_S`` listening after the last move has ended."""
    hit = collision(perf, scene, start.q)
    if hit is not None:
        raise hit
    hobby = servo_kind(start) == "hobby"
    last = max(m.t + m.profile.duration for m in perf.moves)  # the last move's end
    ends = [m.t for m in perf.moves[1:]] + [last]
    steps = [_step(perf, m, hobby, end - m.t) for m, end in zip(perf.moves, ends, strict=True)]
    listen = Step("listen to the last note", at=last, seconds=TAIL_S)
    return plan_steps(start, f"play {perf.source or 'the piece'}", [*steps, listen])


def _step(perf: Performance, move: Move, hobby: bool, seconds: float) -> Step:
    """``move`` sent at its time, lasting ``seconds`` [s] until the next is sent."""
    name = perf.strikes[move.strike].target.note.name
    timed = move.timed or hobby
    return Step(
        f"{name}: {move.kind}", q=move.q, at=move.t,
        duration=move.profile.duration if timed else None,
        speed=None if timed else move.speed, seconds=seconds,
    )  # fmt: skip


def perform(arm: Arm, scene: Scene, perf: Performance) -> Played:
    """Send every move of ``perf`` at its time (``Arm.run`` of ``performance_plan``: the
    strikes where the scene puts the instruments, in millimetres and degrees); in the
    simulator, listen."""
    start = arm.start()
    plan = performance_plan(start, perf, scene)
    world, clock = arm.world, arm.clock
    listener = _listener(arm, perf, scene)
    detach = world.attach(listener) if world is not None else None
    began: list[float] = []
    arm.hold_tool(mallet_held(start, scene))  # kept so, if the piece is interrupted
    try:
        arm.run(plan, say=lambda k, _: began.append(clock.now()) if k == 1 else None)
    finally:
        if detach is not None:
            detach()
    arm.hold_tool(None)  # the piece is over: the mallet is put down
    if world is None:
        return Played(perf)
    heard = tuple(_shifted(c, began[0]) for c in listener.contacts)
    return Played(perf, heard, tuple(listener.dwell), onset_stats(perf.contacts(), heard))


def _listener(arm: Arm, perf: Performance, scene: Scene) -> Listener | MujocoListener:
    """The simulated ear: the mallet's head crossing a bar's top, or MuJoCo's contacts."""
    if scene.physics != "mujoco":
        return Listener(perf.model, scene.instruments, scene.T_world_base)
    from ._heard import MujocoListener

    return MujocoListener(arm.model, perf.model, scene.instruments, scene)


def _shifted(c: Contact, begin: float) -> Contact:
    return Contact(c.time - begin, c.instrument, c.note, c.speed, c.drum)
