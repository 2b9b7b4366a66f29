"""The simulation world: one clock, every simulated device on it, the truth about each arm.

A ``World`` is THE place where a simulated arm's true state lives, and the one
hook for everything that needs it: a scene's physics (grasping, settling), a
distance sensor (``SimArm.analog``), contact detection for music, the pen
trace of a drawing and the 3D viewer are ``Observer``s (called after every
simulation step) or readers of ``SimArm.q()``/``grip()`` and
``World.recording()``.

Time is the world's own. In the default mode it is virtual: nothing happens
until somebody waits on ``world.clock`` (a driver polling its device, a
streamer between waypoints), and waiting runs the simulation forward, faster
than real time. The clock is exact (``sleep(0.0123)`` moves it by exactly that);
the arms are stepped at every multiple of ``1 / rate_hz`` s it passes (their
recordings are on that grid). With
``realtime=True`` the world is paced to the wall clock instead (for the
viewer, for music): a background thread steps it as wall time passes, and
``clock.sleep`` really waits. Observers must be cheap: they run at
``rate_hz`` of simulated time; one that needs 30 Hz checks the time itself.

A still world is not stepped: when, after a run of ``STILL_CHECK`` steps,
every arm is at rest and did not move at all, and every observer says it may
be skipped (``may_skip()``: one without that method never is), the steps up to
the last one are skipped (the arms' recordings get their samples, at the same
angles) and only the last is stepped. So ``wait 600`` on a resting arm costs
milliseconds, not 600 000 steps; a moving arm is stepped as always.

Every method is thread-safe (``world.lock``, re-entrant, guards all state).
"""

from __future__ import annotations

import math
import threading
import time
from collections.abc import Callable
from typing import TYPE_CHECKING, Protocol

import numpy as np
from numpy.typing import NDArray

from .._errors import ArmkitError, InputError
from .._inputs import is_number, shown

if TYPE_CHECKING:
    from ._arm import SimArm
    from ._recording import Recording

F64 = NDArray[np.float64]


class Observer(Protocol):
    """Something that watches the world: called after every simulation step.

    An observer may also have ``on_steps(world, times)``: the world then steps a
    stretch in which no gripper moves at once and calls it once, with the stretch's step
    times [s], shape (N,) (the arms' recordings hold every step: ``SimArm.recent``);
    while any observer lacks it, every step is stepped and observed one by one.
    """

    def on_step(self, world: World, t: float) -> None:
        """The world has just stepped to time ``t`` [s]; read it, or change the scene."""
        ...


MAX_RATE_HZ = 100_000.0  # simulation steps per simulated second, at most
STILL_CHECK = 100  # steps stepped between looks at whether the world is still
MIN_STRETCH = 8  # steps that go at once (``SimArm.run``) rather than one by one, at least


def _may_skip(observer: Observer) -> bool:
    """Whether ``observer`` lets the world skip steps while nothing moves (it says so with
    a ``may_skip()`` method; one without it is stepped always)."""
    may_skip = getattr(observer, "may_skip", None)
    return callable(may_skip) and bool(may_skip())


class WorldClock:
    """The world's time as an ``armkit._clock.Clock``: ``sleep`` advances the simulation
    (virtual mode) or waits for the wall clock while the world keeps pace (real time)."""

    def __init__(self, world: World) -> None:
        self.world = world

    def now(self) -> float:
        """Simulated time [s] since the world was made."""
        return self.world.now()

    def sleep(self, seconds: float) -> None:
        """Let ``seconds`` [s] of simulated time pass (rounded up to whole steps); as every
        ``Clock``, nothing for seconds <= 0 (a deadline already passed). Infinity or not a
        number: InputError (``World.advance``)."""
        if is_number(seconds) and seconds <= 0:  # NaN goes on to advance, which refuses it
            return
        self.world.advance(seconds)


class World:
    """Virtual time, every simulated device on it, and the true state of each arm.

    Args:
        realtime: pace the simulation to the wall clock (see the module doc).
        rate_hz: simulation steps per simulated second (also the recording rate).
        pace: in real-time mode, simulated seconds per wall second (1 = real time).
        record_s: how many seconds of simulated time each arm's recording keeps [s].
    """

    def __init__(
        self,
        *,
        realtime: bool = False,
        rate_hz: float = 1000.0,
        pace: float = 1.0,
        record_s: float = 120.0,
    ) -> None:
        if not (is_number(rate_hz) and 1.0 <= rate_hz <= MAX_RATE_HZ):  # NaN fails too
            raise InputError(
                f"rate_hz must be 1..{MAX_RATE_HZ:g} simulation steps per simulated second "
                f"(1000 = 1 ms steps, the default), got {shown(rate_hz)}"
            )
        for name, value, what in (
            ("pace", pace, "simulated seconds per wall second (1 = real time, 2 = twice as fast)"),
            ("record_s", record_s, "seconds of simulated time each arm's recording keeps"),
        ):
            if not (is_number(value) and math.isfinite(value) and value > 0):
                raise InputError(f"{name} must be a number > 0 of {what}, got {shown(value)}")
        self.realtime, self.rate_hz, self.pace = realtime, float(rate_hz), float(pace)
        self.dt = 1.0 / self.rate_hz
        self.record_rows = max(2, round(record_s * self.rate_hz))
        self.lock = threading.RLock()
        self.clock = WorldClock(self)
        self._t = 0.0  # the clock [s]
        self._steps = 0  # grid steps done: the arms are at time _steps * dt <= _t
        self._in_step = False
        self._arms: dict[str, SimArm] = {}
        self._observers: list[Observer] = []
        self._closers: list[Callable[[], None]] = []
        self._wall0 = time.monotonic()
        self._running = realtime
        self._pacer: threading.Thread | None = None  # started with the first arm or observer
        self._work = 0.0  # [s] wall time spent stepping, in real-time mode
        self._worked = 0.0  # [s] the simulated time that stepping covered

    # -- time ---------------------------------------------------------------
    def now(self) -> float:
        """Simulated seconds since the world was made."""
        with self.lock:
            if self.realtime and not self._in_step:
                self._catch_up()
            return self._t

    def device_time(self) -> float:
        """The time a simulated device reads [s]: ``now()`` without stepping anything. In
        real-time mode the wall clock's (paced) time, so a device answering its host
        never waits for the arms' physics to catch up (the arms follow the devices'
        setpoints, which are functions of time); in virtual mode the same as ``now()``."""
        if not self.realtime:
            return self._t
        return max(self._t, (time.monotonic() - self._wall0) * self.pace)

    def advance(self, seconds: float) -> None:
        """Run the simulation for ``seconds`` [s] of simulated time, a finite number >= 0
        (0: nothing). In real-time mode this waits as long.

        Raises:
            InputError: ``seconds`` is not a number, negative, NaN or infinite (time does
                not run backwards; ``clock.sleep`` is the one that ignores a past deadline).
        """
        if not (type(seconds) is float and 0.0 <= seconds < math.inf):  # the usual case, fast
            if not (is_number(seconds) and 0.0 <= seconds < math.inf):  # NaN fails too
                raise InputError(
                    "advance takes a finite number of seconds >= 0 of simulated time, "
                    f"got {shown(seconds)}"
                )
            seconds = float(seconds)
        if seconds == 0.0:
            return
        if self.realtime:
            self._wait_until(self.now() + seconds)
            return
        with self.lock:
            self._run_to(self._t + seconds)

    # -- arms and observers ----------------------------------------------------
    def arms(self) -> tuple[SimArm, ...]:
        """Every simulated arm, in the order they were added."""
        with self.lock:
            return tuple(self._arms.values())

    def arm(self, name: str | None = None) -> SimArm:
        """The arm called ``name``; None: the only arm (ArmkitError if there are 0 or several)."""
        with self.lock:
            if name is None and len(self._arms) == 1:
                return next(iter(self._arms.values()))
            if name is not None and name in self._arms:
                return self._arms[name]
            names = ", ".join(self._arms) or "none yet"
            asked = "single arm" if name is None else f"arm {name!r}"
            raise ArmkitError(f"this world has no {asked} to pick; its arms: {names}")

    def add_arm(self, arm: SimArm) -> SimArm:
        """Put ``arm`` in this world (the factory does this when it opens a simulated
        device); its name must be new. Returns it."""
        with self.lock:
            if arm.name in self._arms:
                raise ArmkitError(f"this world already has an arm called {arm.name!r}")
            arm.join(self.lock, self.record_rows, self.now())
            self._arms[arm.name] = arm
            self._start_pacing()
        return arm

    def remove_arm(self, name: str) -> None:
        """Take the arm called ``name`` out of this world (its device failed to open)."""
        with self.lock:
            self._arms.pop(name, None)

    def unique_name(self, name: str) -> str:
        """``name``, or ``name-2``, ``name-3``, ... if an arm of that name is already here."""
        with self.lock:
            k, found = 1, name
            while found in self._arms:
                k += 1
                found = f"{name}-{k}"
            return found

    def attach(self, observer: Observer) -> Callable[[], None]:
        """Call ``observer.on_step(world, t)`` after every step; returns ``detach()``.

        Raises:
            InputError: ``observer`` has no ``on_step(world, t)`` method (None, a function,
                a class instead of an instance); nothing is attached.
        """
        if isinstance(observer, type) or not callable(getattr(observer, "on_step", None)):
            got = (
                f"the class {observer.__name__} (attach an instance of it)"
                if isinstance(observer, type)
                else shown(observer)
            )
            raise InputError(
                "an observer must be an object with a method on_step(world, t), called after "
                f"every simulation step (armkit.sim.Observer), got {got}"
            )
        with self.lock:
            self._observers.append(observer)
            self._start_pacing()

        def detach() -> None:
            with self.lock:
                if observer in self._observers:
                    self._observers.remove(observer)

        return detach

    def recording(self, name: str | None = None) -> Recording:
        """The true joint angles of arm ``name`` (None: the only arm), one sample per step
        for the last ``record_s`` seconds."""
        return self.arm(name).recording()

    def on_close(self, action: Callable[[], None]) -> None:
        """Run ``action`` (once) when the world is closed."""
        with self.lock:
            self._closers.append(action)

    def close(self) -> None:
        """Stop pacing (real-time mode) and run the close actions. Safe to call twice."""
        self._running = False
        if self._pacer is not None and self._pacer is not threading.current_thread():
            self._pacer.join(timeout=1.0)
        with self.lock:
            closers, self._closers = self._closers, []
        for action in closers:
            action()

    def _start_pacing(self) -> None:
        """In real-time mode, start the thread that steps the world (once, and only when
        there is something to step: a world of lone devices needs no thread)."""
        if self._running and self._pacer is None:
            self._pacer = threading.Thread(target=self._pace, name="armkit-world", daemon=True)
            self._pacer.start()

    # -- stepping -----------------------------------------------------------------
    def _step(self, count: int) -> None:
        """``count`` steps of every arm and observer (the caller holds the lock)."""
        if not self._arms and not self._observers:
            self._steps += count  # nothing to integrate: jump
            return
        arms, observers = tuple(self._arms.values()), tuple(self._observers)
        stretches = all(callable(getattr(o, "on_steps", None)) for o in observers)
        self._in_step = True
        try:
            while count > 0:
                n = min(count, STILL_CHECK)
                before = [(arm.q(), arm.grip()) for arm in arms] if count > n + 1 else None
                for arm in arms:
                    arm.begin()
                if not (stretches and n >= MIN_STRETCH and self._stretch(arms, observers, n)):
                    self._one_by_one(arms, observers, n)
                count -= n
                if before is not None and _still(arms, observers, before):
                    for arm in arms:
                        arm.hold((self._steps + 1) * self.dt, self.dt, count - 1)
                    self._steps += count - 1
                    count = 1
        finally:
            self._in_step = False

    def _one_by_one(
        self, arms: tuple[SimArm, ...], observers: tuple[Observer, ...], n: int
    ) -> None:
        """``n`` steps, each arm then each observer at each."""
        dt = self.dt
        for _ in range(n):
            self._steps += 1
            t = self._steps * dt
            for arm in arms:
                arm.step(t, dt)
            for observer in observers:
                observer.on_step(self, t)

    def _stretch(self, arms: tuple[SimArm, ...], observers: tuple[Observer, ...], n: int) -> bool:
        """``n`` steps at once, if every arm can (``SimArm.runnable``: no jaws move in
        them) and every observer takes a stretch (``on_steps``); False: nothing done."""
        times = np.arange(self._steps + 1, self._steps + n + 1, dtype=np.float64) * self.dt
        if not all(arm.runnable(times) for arm in arms):
            return False
        for arm in arms:
            arm.run(times, self.dt)
        self._steps += n
        for observer in observers:
            observer.on_steps(self, times)  # type: ignore[attr-defined]
        return True

    def _run_to(self, t: float) -> None:
        """Move the clock to ``t`` [s] and step the arms over every grid time up to it."""
        self._t = max(self._t, t)
        due = math.floor(self._t * self.rate_hz + 1e-9)
        if due > self._steps:
            self._step(due - self._steps)

    def _catch_up(self) -> None:
        before, began = self._steps, time.monotonic()
        self._run_to((began - self._wall0) * self.pace)
        if self._steps > before and (self._arms or self._observers):
            self._work += time.monotonic() - began
            self._worked += (self._steps - before) * self.dt

    def slowdown(self) -> float:
        """In real-time mode, how many times slower than its pace the world's stepping
        has run: the wall time spent stepping over the simulated time it covered, times
        the pace (1.0: it keeps pace; a busy machine makes it more, and everything in it
        -- a job, the view -- slows down with it). Always 1.0 in virtual mode."""
        with self.lock:
            if not self.realtime or self._worked <= 0.0:
                return 1.0
            return max(1.0, self._work * self.pace / self._worked)

    def _wait_until(self, t: float) -> None:
        wall = self._wall0 + t / self.pace
        time.sleep(max(0.0, wall - time.monotonic()))
        with self.lock:
            self._catch_up()
            self._run_to(t)

    def _pace(self) -> None:
        """The real-time thread: step the world as the wall clock passes."""
        while self._running:
            with self.lock:
                self._catch_up()
                busy = bool(self._arms or self._observers)
            step_wall = 1.0 / (self.rate_hz * self.pace)
            if not busy:
                time.sleep(0.01)
                continue
            next_due = self._wall0 + (self._steps + 1) * step_wall
            time.sleep(max(0.0, next_due - time.monotonic()))


def _still(
    arms: tuple[SimArm, ...], observers: tuple[Observer, ...], before: list[tuple[F64, float]]
) -> bool:
    """Every arm at rest and exactly where it was ``before`` (joint angles [rad], gripper
    opening [m]), and every observer content to be skipped."""
    return (
        all(arm.at_rest() for arm in arms)
        and all(
            arm.grip() == grip and np.array_equal(arm.q(), q)
            for arm, (q, grip) in zip(arms, before, strict=True)
        )
        and all(_may_skip(observer) for observer in observers)
    )
