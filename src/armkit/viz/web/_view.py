"""``View``: a live 3D page of an arm on its table (viser, served from this process).

The page is viser's own client, bundled in the viser package and served by the
view itself, so it works with no network. It shows the arm on its table and
the scene's objects (``armkit.scene.Scene``: boards, cubes, containers, paper,
instruments) in the scene's frame. A thread reads the ``StateSource``
``rate_hz`` times a second and sends what changed (the link poses, the jaws,
the cubes that moved, the tool's trail, the ink on the paper where the tool
touched it); a target marker shows whether a
gripper target is reachable, on a cube and clear (the scene's clearance check).
"""

from __future__ import annotations

import contextlib
import io
import threading
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np
import viser
from numpy.typing import ArrayLike, NDArray

from ..._errors import ArmkitError, InputError
from ..._primitives import Label, Primitive, Sphere
from ...scene import Scene, cube_primitive
from .._address import serve_address
from .._arm_shapes import TRAIL_COLOUR, arm_primitives, reach_of, table_primitive
from .._chunked import CHUNK, ChunkedLine
from .._ink import Ink
from .._scene_shapes import scene_primitives
from .._state import ObjectPose, Snapshot, StateSource
from .._target import TargetCheck, check_target
from ._render import Renderer
from ._unreadable import quiet_unreadable

F64 = NDArray[np.float64]
OK_COLOUR = (30, 180, 60)
CONTACT_RADIUS = 0.002  # [m] a contact point as the view draws it
CONTACT_COLOUR = (255, 140, 0)  # orange
BAD_COLOUR = (220, 30, 30)
TRAIL_STEP = 0.001  # [m] the trail grows when the tool moved this far


@dataclass(frozen=True)
class ViewStats:
    """How the view kept up: ``updates`` sent to the page (frames where the arm
    moved), ``reads`` of the source, since ``started`` [s, time.monotonic]."""

    updates: int
    reads: int
    started: float


class View:
    """A live 3D page of ``source``'s arm (see the module doc).

    Args:
        source: what to show (``WorldSource``, ``ArmSource``, ``LiveSource``).
        scene: what is on the table (its cubes move as the source's objects say);
            the table plane is always drawn.
        extra: more primitives to draw once (scene frame).
        host, port: where to serve the page; 127.0.0.1 = this computer only, 0 = any free port.
        rate_hz: how often the source is read [1/s].
        frames: draw each joint frame's axes.
        trail: the most tool positions the trail keeps (0 = no trail).
    """

    def __init__(
        self,
        source: StateSource,
        *,
        scene: Scene | None = None,
        extra: Sequence[Primitive] = (),
        host: str = "127.0.0.1",
        port: int = 8080,
        rate_hz: float = 30.0,
        frames: bool = False,
        trail: int = 600,
    ) -> None:
        if not 0 < rate_hz <= 1000:
            raise InputError(f"rate must be in (0, 1000] Hz, got {rate_hz}")
        self.source = source
        self.model = source.model
        self.scene = scene
        self.T_world_base = np.eye(4) if scene is None else scene.T_world_base
        self._objects: dict[str, F64] = {}
        self.ink = Ink(scene.sheets if scene is not None else ())
        self.rate_hz = rate_hz
        self.frames = frames
        self.server = _serve(host, port)
        quiet_unreadable()  # a client's garbage is one line, not a traceback
        self.host = host
        self.renderer = Renderer(self.server.scene)
        self._trail = ChunkedLine("/trail", TRAIL_COLOUR, 2.0, max(trail, CHUNK + 1))
        self._trail_max = trail
        self._last_q: F64 | None = None
        self._shown_contacts = 0
        self._state: Snapshot | None = None
        self._stop = threading.Event()
        self._thread: threading.Thread | None = None
        self._lock = threading.Lock()
        self._updates = 0
        self._reads = 0
        self._started = time.monotonic()
        self.target: TargetCheck | None = None
        self._listeners: list[Callable[[], None]] = []
        self._setup_page(extra)

    @property
    def url(self) -> str:
        """Where the page is (http://host:port/)."""
        host = "127.0.0.1" if self.host in ("0.0.0.0", "::", "") else self.host
        return f"http://{host}:{self.server.get_port()}/"

    @property
    def state(self) -> Snapshot | None:
        """The state last shown (None before the first update)."""
        return self._state

    def stats(self) -> ViewStats:
        """Counts of updates and reads so far."""
        return ViewStats(self._updates, self._reads, self._started)

    def start(self) -> View:
        """Follow the source from a thread, ``rate_hz`` times a second."""
        if self._thread is None:
            self._thread = threading.Thread(target=self._run, name="armkit-view", daemon=True)
            self._thread.start()
        return self

    def on_update(self, listener: Callable[[], None]) -> None:
        """Call ``listener()`` after every update that showed a new state."""
        self._listeners.append(listener)

    def update(self) -> bool:
        """Read the source once and send what changed; True if the arm moved."""
        if self._show(self.source.state()):
            for listener in self._listeners:
                listener()
            return True
        return False

    def _show(self, state: Snapshot) -> bool:
        with self._lock:
            self._reads += 1
            moved = self._last_q is None or not np.array_equal(state.q, self._last_q)
            grip_changed = self._state is None or state.grip != self._state.grip
            self._state = state
            objects = self._moved_objects(state.objects)
            touching = self._contacts(state.contacts)
            if not (moved or grip_changed or objects or touching):
                return False
            self._last_q = state.q.copy()
            with self.server.atomic():
                self.renderer.draw(
                    arm_primitives(
                        self.model,
                        state.q,
                        state.grip,
                        frames=self.frames,
                        T_world_base=self.T_world_base,
                    )
                )
                self.renderer.draw(objects)
                self._grow_trail(state.q)
            self._updates += 1
            return True

    def _contacts(self, points: F64 | None) -> bool:
        """Draw a physics engine's contact points (small spheres; those of the last
        state no longer touching removed); whether anything changed."""
        if points is None or (len(points) == 0 and self._shown_contacts == 0):
            return False
        with self.server.atomic():
            self.renderer.draw(
                Sphere(f"/contacts/{k}", p, CONTACT_RADIUS, CONTACT_COLOUR)
                for k, p in enumerate(points)
            )
            for k in range(len(points), self._shown_contacts):
                self.renderer.remove(f"/contacts/{k}")
        self._shown_contacts = len(points)
        return True

    def _moved_objects(self, objects: tuple[ObjectPose, ...]) -> list[Primitive]:
        """Cube primitives of the objects whose pose changed since last shown."""
        if self.scene is None:
            return []
        cubes = {c.name: c for c in self.scene.cubes}
        out: list[Primitive] = []
        for obj in objects:
            last = self._objects.get(obj.name)
            if obj.name in cubes and (last is None or not np.array_equal(last, obj.T)):
                self._objects[obj.name] = obj.T
                out.append(cube_primitive(cubes[obj.name], self.scene, obj.T))
        return out

    def set_target(self, position: ArrayLike, pitch: float | None = None) -> TargetCheck:
        """Check the gripper target ``position`` [m] (arm base frame), shape (3,), at
        ``pitch`` [rad] (None: any) against the scene and show it: a green ball when
        reachable and clear (saying which cube it is on), red with the reason otherwise."""
        seed = None if self._state is None else self._state.q
        check = check_target(self.model, position, pitch, seed, self.scene)
        colour = OK_COLOUR if check.ok else BAD_COLOUR
        text = "reachable" if check.ok else check.reason
        text = f"on {check.on}: {text}" if check.on else text
        where = self.T_world_base[:3, :3] @ check.position + self.T_world_base[:3, 3]
        with self._lock:
            self.target = check
            self.renderer.draw(
                [
                    Sphere("/target/ball", where, 0.012, colour),
                    Label("/target/why", where + np.array([0.0, 0.0, 0.02]), text, colour),
                ]
            )
        return check

    def clear_trail(self) -> None:
        """Forget the tool's trail."""
        with self._lock:
            for name in self._trail.clear():
                self.renderer.remove(name)

    def close(self) -> None:
        """Stop following and stop serving the page."""
        self._stop.set()
        if self._thread is not None:
            self._thread.join(timeout=2.0)
        with contextlib.redirect_stdout(io.StringIO()):  # viser's "Server stopped"
            self.server.stop()

    def __enter__(self) -> View:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def _run(self) -> None:
        period = 1.0 / self.rate_hz
        deadline = time.monotonic()
        while not self._stop.is_set():
            self.update()
            deadline = max(deadline + period, time.monotonic() - period)
            self._stop.wait(max(0.0, deadline - time.monotonic()))

    def _grow_trail(self, q: F64) -> None:
        """The tool's trail, and the ink on the scene's paper where the tool touches it."""
        from ...kinematics import fk

        tip = (self.T_world_base @ fk(self.model, q))[:3, 3]
        stroke = self.ink.add(tip)
        if stroke is not None:
            self.renderer.draw_one(stroke)
        trail = self._trail.points
        if self._trail_max <= 0 or (trail and np.linalg.norm(tip - trail[-1]) < TRAIL_STEP):
            return
        newest, removed = self._trail.add(tip)
        for name in removed:
            self.renderer.remove(name)
        if newest is not None:
            self.renderer.draw_one(newest)

    def _setup_page(self, extra: Sequence[Primitive]) -> None:
        s = self.server
        s.gui.configure_theme(show_share_button=False, control_width="medium")
        s.scene.set_up_direction("+z")
        s.scene.world_axes.visible = False
        # Lights of our own, no environment map: the page looks the same from the
        # first frame on (an image-based map loads later and would change the colours).
        s.scene.configure_environment_map(hdri=None)
        s.scene.configure_default_lights(enabled=False, cast_shadow=False)
        s.scene.add_light_hemisphere(
            "/lights/sky", sky_color=(255, 255, 255), ground_color=(120, 120, 130), intensity=2.2
        )
        s.scene.add_light_directional("/lights/sun", intensity=1.6, position=(0.3, -0.5, 1.0))
        reach = reach_of(self.model)
        x, y, z = self.T_world_base[:3, 3].tolist()
        s.initial_camera.position = (x + 1.1 * reach, y - 1.0 * reach, z + 0.95 * reach)
        s.initial_camera.look_at = (x + 0.3 * reach, y, z + 0.3 * reach)
        s.initial_camera.up = (0.0, 0.0, 1.0)
        objects = scene_primitives(self.scene) if self.scene is not None else []
        self.renderer.draw([table_primitive(self.model, self.scene), *objects, *extra])


def _serve(host: str, port: int) -> viser.ViserServer:
    """viser's server on ``host``, ``port`` or the next free port above (checked first:
    viser, given an address it cannot bind, tries port after port and never returns)."""
    port = serve_address(host, port, exact=False).port
    try:
        with contextlib.redirect_stdout(io.StringIO()):  # viser's banner: we print our own URL
            return viser.ViserServer(host=host, port=port, verbose=False)
    except OSError as exc:
        raise ArmkitError(f"cannot serve the view on {host}:{port}: {exc}") from None
