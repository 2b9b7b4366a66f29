"""``--view`` and ``--gif`` for any command that moves the arm: one shared mechanism.

A command module gets both options with two calls:

    from ._watch import add_watch_options, watched_arm

    add_watch_options(parser)                   # in add_commands
    with watched_arm(args, scene) as arm:       # in the handler, instead of opening the arm
        ...                                     # the job

``watched_arm`` checks the options (and every file they write) before anything
moves, opens the arm of ``--arm/--driver/--port`` as the other commands do (a
simulated arm keeps its pose in its state file), attaches the scene's physics
to a simulated arm (cubes are grasped, carried and set down), and then:

- ``--view``: runs the simulation in real time (the job takes as long as on the
  real arm) and serves the live 3D view of it while the command runs, waiting up
  to ``--view-wait`` s for a page to open first;
- ``--gif FILE.gif``: records the world ``--fps`` times per simulated second and
  writes the animation when the job is done (matplotlib, headless).

A command that opens its arm itself uses ``watch_world(args)`` (the world to
open it in) and ``watching(args, arm, scene)`` (the rest) instead.
"""

from __future__ import annotations

import argparse
import contextlib
import math
import time
import warnings
from collections.abc import Iterator
from pathlib import Path
from typing import Any

from .._errors import ArmkitError, ArmkitWarning, InputError
from .._files import check_output_path

WAIT_LONGEST = 600.0  # [s] --view-wait


def add_watch_options(p: argparse.ArgumentParser) -> None:
    """Add ``--view``, ``--view-port``, ``--view-wait``, ``--gif`` and ``--fps`` to ``p``."""
    g = p.add_argument_group("watching (simulated arms)")
    g.add_argument("--view", action="store_true", help="serve the live 3D view while this runs; the simulation runs in real time (web extra)")  # fmt: skip
    g.add_argument("--view-port", type=int, default=8080, metavar="PORT", help="TCP port of the view's page (default 8080; 0 = any free)")  # fmt: skip
    g.add_argument("--view-wait", type=float, default=10.0, metavar="S", help="with --view, wait up to S seconds for a page to open before moving (default 10; 0 = do not wait)")  # fmt: skip
    g.add_argument("--contacts", action="store_true", help="with --view and --physics mujoco, draw where MuJoCo's bodies touch (orange dots)")  # fmt: skip
    g.add_argument("--gif", metavar="FILE.gif", help="write an animation of the simulated arm doing this (plot extra)")  # fmt: skip
    g.add_argument("--fps", type=float, default=15.0, metavar="HZ", help="animation frames per second of simulated time [1/s] (default 15)")  # fmt: skip


def check_watch_options(args: argparse.Namespace) -> None:
    """Refuse bad watch options before anything moves (the GIF's file included)."""
    view, gif = getattr(args, "view", False), getattr(args, "gif", None)
    if not (view or gif):
        return
    if args.driver_name != "sim" and args.port != "emu":
        flag = "--view" if view else "--gif"
        raise InputError(f"{flag} watches a simulated arm; drop --driver {args.driver_name} (or use --port emu), or follow a real arm with 'armkit view'")  # fmt: skip
    if not 0 <= args.view_port <= 65535:
        raise InputError(f"--view-port must be 0..65535, got {args.view_port}")
    if not (math.isfinite(args.view_wait) and 0 <= args.view_wait <= WAIT_LONGEST):
        raise InputError(f"--view-wait must be 0..{WAIT_LONGEST:.0f} s, got {args.view_wait}")
    if not (math.isfinite(args.fps) and 1 <= args.fps <= 60):
        raise InputError(f"--fps must be 1..60 frames per second, got {args.fps}")
    if gif:
        check_output_path(gif, "--gif", (".gif",))


def watch_world(args: argparse.Namespace) -> Any:
    """The World to open the arm in: a real-time one for ``--view``, else None (the
    factory's usual virtual-time world). Checks the options first."""
    check_watch_options(args)
    if not getattr(args, "view", False):
        return None
    web_module()  # the extra is there before anything is opened
    from ..sim import World

    return World(realtime=True)


class SlowdownWarning(ArmkitWarning):
    """A real-time simulation could not keep pace with the wall clock."""


@contextlib.contextmanager
def watched_arm(args: argparse.Namespace, scene: Any = None) -> Iterator[Any]:
    """The Arm of ``--arm/--driver/--port`` (with ``scene``), watched as the options say
    (see the module doc); closed, and the GIF written, when the block ends."""
    from ..arm import Arm
    from ..model import load_model
    from ._kept import open_kept

    model = load_model(args.arm)
    world = watch_world(args)
    try:
        driver = open_kept(model, args, world)
        with (
            Arm(model, driver, scene=scene) as arm,
            kept_objects(args, arm, scene),
            watching(args, arm, scene),
        ):
            yield arm
        if world is not None:
            say_slowdown(world)
    finally:
        if world is not None:
            world.close()


SLOWDOWN_SAID = 1.5  # a real-time world this many times slower than real time is said


def say_slowdown(world: Any) -> None:
    """Warn if a real-time world could not keep pace (a busy machine): the job and the
    view ran slower than real time and would otherwise say nothing of it."""
    factor = world.slowdown()
    if factor >= SLOWDOWN_SAID:
        warnings.warn(
            f"the simulation ran up to {factor:.1f}x slower than real time (this machine is "
            "busy): the job and the view took that much longer than on the arm",
            SlowdownWarning,
            stacklevel=2,
        )


@contextlib.contextmanager
def watching(args: argparse.Namespace, arm: Any, scene: Any = None) -> Iterator[Any]:
    """Attach the scene's physics, the GIF recorder and the view to ``arm``'s world for
    the block (which gets the ``ScenePhysics``, None without a scene or a simulation);
    then write the GIF (only when the block ends without an error)."""
    world = arm.world
    if world is None:
        yield None
        return
    from ..viz import cubes, publisher_of

    physics = _physics(arm, scene)
    publisher = publisher_of(world)
    if publisher is not None:
        publisher.objects = lambda: cubes(physics)
    recorder = None
    if getattr(args, "gif", None):
        from ..viz import GifRecorder  # the pictures' code only for a GIF

        recorder = GifRecorder(world.arm(), args.fps, physics)
    detach = world.attach(recorder) if recorder is not None else None
    with contextlib.ExitStack() as stack:
        if getattr(args, "view", False):
            stack.enter_context(_served(args, world, physics, scene))
        yield physics
    if detach is not None and recorder is not None:
        detach()
        _write_gif(arm, recorder, Path(args.gif), scene)


def _physics(arm: Any, scene: Any) -> Any:
    """The scene's physics on the arm's world: the one already attached (kept objects),
    else a new one."""
    if scene is None:
        return None
    from ..tasks import attach_scene

    return attach_scene(arm, scene)


@contextlib.contextmanager
def kept_objects(args: argparse.Namespace, arm: Any, scene: Any) -> Iterator[None]:
    """On a simulated arm kept between runs (``--driver sim``, no port or ``--port FILE``;
    not ``emu``), the scene's objects are kept in their state file too: loaded and attached
    to the world for the block, locked while in use, and written back when the block
    changed them (a refused command changes nothing, so writes nothing)."""
    if scene is None or arm.world is None or args.driver_name != "sim" or args.port == "emu":
        yield
        return
    from .._lock import exclusive
    from ..scene import load_physics, physics_text, save_physics, scene_state_file
    from ..sim import kept_key
    from ..tasks import attach_scene

    path = scene_state_file(scene, kept_key(arm.model, args.port))
    lock = exclusive(path, f"the simulated objects of {scene.name}")
    try:
        physics = load_physics(path, scene)
        before = physics_text(physics)
        physics = attach_scene(arm, scene, physics) or physics  # MuJoCo's, if the scene says
        yield
    finally:
        if physics_text(physics) != before:
            save_physics(path, physics)
        lock.release()


@contextlib.contextmanager
def _served(args: argparse.Namespace, world: Any, physics: Any, scene: Any) -> Iterator[None]:
    web = web_module()
    from ..viz import WorldSource

    source = WorldSource(world, physics=physics, contacts=bool(getattr(args, "contacts", False)))
    with web.View(source, scene=scene, port=args.view_port) as view:
        view.start()
        print(f"armkit: live view at {view.url}", flush=True)
        if args.view_wait > 0 and not _page_opened(view, args.view_wait):
            print(f"armkit: no page opened within {args.view_wait:g} s; going on", flush=True)
        yield
        time.sleep(3.0 / view.rate_hz)  # the last state reaches the page


def _page_opened(view: Any, seconds: float) -> bool:
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        if view.server.get_clients():
            return True
        time.sleep(0.05)
    return False


def _write_gif(arm: Any, recorder: Any, path: Path, scene: Any) -> None:
    from ..viz import write_gif

    frames = recorder.frames
    write_gif(arm.model, frames, path, scene=scene, fps=recorder.fps)
    took = frames[-1].t - frames[0].t if frames else 0.0
    print(f"armkit: wrote {path} ({len(frames)} frames, {took:.1f} s of motion)")


def web_module() -> Any:
    """``armkit.viz.web`` (imports viser), or ArmkitError saying how to install it."""
    try:
        from ..viz import web
    except ImportError as exc:
        raise ArmkitError(f"the 3D view needs viser ({exc}): pip install 'armkit[web]'") from None
    return web
