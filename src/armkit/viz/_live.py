"""Following a simulated arm that ANOTHER process moves (``armkit view --follow``).

A simulated arm the CLI keeps between processes lives in its state file
(``armkit.connect.sim_state_file``), locked by the one process that moves it.
Beside it are two small files, the live channel:

- ``<state>.follow``: a follower (``LiveSource``) touches it every second;
- ``<state>.live``: while a follower is there, the moving process's
  ``LivePublisher`` (an Observer of its World) writes the arm's truth into it
  ``PUBLISH_HZ`` times a simulated second: time, joint angles, gripper opening,
  the cubes of its ``ScenePhysics`` (JSON, atomic replace). It also paces its
  virtual-time world to the wall clock while followed, so a task that would run
  faster than real time is seen as it would happen on a real arm.

Nobody following: the publisher only looks at the ``.follow`` file's time now
and then (cheap). The follower shows the newer of the live file and the state
file (the pose a finished process left).
"""

from __future__ import annotations

import contextlib
import json
import math
import os
import time
import weakref
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from .._errors import ArmkitError, InputError
from .._files import write_atomic
from ..model import ArmModel
from ._state import ObjectPose, Snapshot, Truth

if TYPE_CHECKING:
    from ..connect import World

F64 = NDArray[np.float64]
PUBLISH_HZ = 100.0  # [1/s of simulated time] live snapshots while followed
FOLLOWED_S = 3.0  # [s] a .follow file touched this recently means somebody watches
LOOK_S = 0.25  # [s of wall time] between looks at the .follow file
TOUCH_S = 1.0  # [s] how often a follower touches its file


def live_path(state: Path) -> Path:
    """The live channel file beside the state file ``state``."""
    return state.with_name(state.name + ".live")


def follow_path(state: Path) -> Path:
    """The file a follower touches beside the state file ``state``."""
    return state.with_name(state.name + ".follow")


class LivePublisher:
    """An Observer writing ``arm``'s truth to the live file of ``state`` while somebody
    follows it (see the module doc). ``objects`` gives the cubes' poses (set by
    whoever attaches a ``ScenePhysics``)."""

    def __init__(self, arm: Truth, state: Path) -> None:
        self.arm = arm
        self.live, self.follow = live_path(state), follow_path(state)
        self.objects: Callable[[], tuple[ObjectPose, ...]] = tuple
        self._next_t = 0.0
        self._next_look = 0.0
        self._followed = False
        self._anchor: tuple[float, float] | None = None  # (simulated t, wall) at first publish

    def on_step(self, world: World, t: float) -> None:
        """Publish (and pace to the wall clock) ``PUBLISH_HZ`` times a second when followed."""
        if t < self._next_t:
            return
        self._next_t = t + 1.0 / PUBLISH_HZ
        if not self._watched():
            self._anchor = None
            return
        if not world.realtime:
            self._pace(t)
        self.publish()

    def on_steps(self, world: World, times: F64) -> None:
        """A stretch of steps at ``times`` [s] (no jaws moved in it): published as
        ``on_step`` would at each, with the angles each step recorded."""
        rows: F64 | None = None
        for k, t in enumerate(times.tolist()):
            if t < self._next_t:
                continue
            self._next_t = t + 1.0 / PUBLISH_HZ
            if not self._watched():
                self._anchor = None
                continue
            if rows is None:
                rows = self.arm.recent(len(times))
            if not world.realtime:
                self._pace(t)
            self.publish(rows[k])

    def may_skip(self) -> bool:
        """The world may skip steps while nothing moves, unless somebody follows it (then
        its time keeps pace with the wall clock, still or not)."""
        return not self._watched()

    def publish(self, q: F64 | None = None) -> None:
        """Write the live file now (the arm at ``q`` [rad], shape (dof,); None: as it is);
        its time is the wall clock's (``time.monotonic``, the same in every process), so a
        follower knows how old what it shows is."""
        q = self.arm.q() if q is None else q
        state = Snapshot(time.monotonic(), q, self.arm.grip(), self.objects())
        write_atomic(self.live, encode(state), durable=False)

    def _watched(self) -> bool:
        wall = time.monotonic()
        if wall >= self._next_look:
            self._next_look = wall + LOOK_S
            try:
                self._followed = time.time() - self.follow.stat().st_mtime < FOLLOWED_S
            except OSError:
                self._followed = False
        return self._followed

    def _pace(self, t: float) -> None:
        wall = time.monotonic()
        if self._anchor is None:
            self._anchor = (t, wall)
        ahead = (t - self._anchor[0]) - (wall - self._anchor[1])
        if ahead > 0:
            time.sleep(min(ahead, 1.0))


def publish_live(world: World, arm: Truth, state: Path) -> LivePublisher:
    """Attach a ``LivePublisher`` of ``arm`` (kept in ``state``) to ``world``; remembered
    for ``publisher_of``. The factory calls this for every kept simulated arm."""
    publisher = LivePublisher(arm, state)
    world.attach(publisher)
    _PUBLISHERS[world] = publisher
    return publisher


def publisher_of(world: World) -> LivePublisher | None:
    """The live publisher attached to ``world``, or None (an arm not kept in a file)."""
    return _PUBLISHERS.get(world)


_PUBLISHERS: weakref.WeakKeyDictionary[World, LivePublisher] = weakref.WeakKeyDictionary()


def encode(state: Snapshot) -> str:
    """One snapshot as JSON (SI units)."""
    objects = [{"name": o.name, "T": o.T.ravel().tolist()} for o in state.objects]
    data = {"t": state.t, "q": state.q.tolist(), "grip": state.grip, "objects": objects}
    return json.dumps(data)


def decode(text: str, dof: int) -> Snapshot:
    """A snapshot back from ``encode`` (ValueError if it is not one for ``dof`` joints)."""
    data = json.loads(text)
    q = np.array(data["q"], dtype=np.float64)
    if q.shape != (dof,) or not np.all(np.isfinite(q)):
        raise InputError(f"expected {dof} joint angles, got {data['q']!r}")
    objects = tuple(
        ObjectPose(str(o["name"]), np.array(o["T"], dtype=np.float64).reshape(4, 4))
        for o in data["objects"]
    )
    return Snapshot(float(data["t"]), q, float(data["grip"]), objects)


@dataclass
class _Seen:
    stamp: tuple[int, int]  # (mtime_ns, size) of the file read
    state: Snapshot


class LiveSource:
    """Follow the simulated ``model`` that other processes move, through its state file
    ``state`` and the live channel beside it (see the module doc), at wall time."""

    def __init__(self, model: ArmModel, state: Path) -> None:
        self._model = model
        self.state_file, self.live = state, live_path(state)
        self.follow = follow_path(state)
        self._touched = -math.inf
        self._seen: dict[Path, _Seen] = {}
        self._objects: tuple[ObjectPose, ...] = ()

    @property
    def model(self) -> ArmModel:
        """The arm being shown."""
        return self._model

    def now(self) -> float:
        """Wall time [s] (``time.monotonic``)."""
        return time.monotonic()

    def state(self, t: float | None = None) -> Snapshot:
        """The newest of the live snapshot and the kept state (home if neither exists);
        its ``t`` is when the other process published it [s, ``time.monotonic``]."""
        if t is not None:
            raise ArmkitError("another process's arm can only be followed now; give t=None")
        self._touch()
        live, kept = self._read(self.live, self._live), self._read(self.state_file, self._kept)
        newest = max(
            (s for s in (live, kept) if s is not None), key=lambda s: s.stamp, default=None
        )
        if newest is None:
            return Snapshot(self.now(), self.model.home.copy(), self.model.gripper.width_max)
        if newest.state.objects:
            self._objects = newest.state.objects
        found = newest.state
        return Snapshot(found.t, found.q, found.grip, self._objects)

    def close(self) -> None:
        """Stop following (the publisher stops writing within ``FOLLOWED_S``)."""
        with contextlib.suppress(OSError):
            self.follow.unlink(missing_ok=True)

    def _touch(self) -> None:
        if time.monotonic() - self._touched >= TOUCH_S:
            self._touched = time.monotonic()
            write_atomic(self.follow, f"{os.getpid()}\n", durable=False)

    def _read(self, path: Path, parse: Callable[[str], Snapshot]) -> _Seen | None:
        try:
            st = path.stat()
            stamp = (st.st_mtime_ns, st.st_size)
            seen = self._seen.get(path)
            if seen is None or seen.stamp != stamp:
                seen = _Seen(stamp, parse(path.read_text(encoding="utf-8")))
                self._seen[path] = seen
            return seen
        except (OSError, ValueError, KeyError, TypeError):
            return self._seen.get(path)

    def _live(self, text: str) -> Snapshot:
        return decode(text, self.model.dof)

    def _kept(self, text: str) -> Snapshot:
        data = json.loads(text)
        q = np.radians(np.array(data["q_deg"], dtype=np.float64))
        if q.shape != (self.model.dof,):
            raise InputError("not this arm's state")
        return Snapshot(self.now(), q, float(data["grip_mm"]) / 1000.0)
