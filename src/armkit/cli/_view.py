"""``armkit view``: the arm in 3D in the browser, to watch, teach, and take pictures.

viser (the ``web`` extra) and matplotlib are imported only when the command runs.
"""

from __future__ import annotations

import argparse
import time
from pathlib import Path
from typing import Any

from .._errors import InputError
from .._progress import Progress
from .._terminal import count
from ._view_inputs import FOLLOW_RATE as FOLLOW_RATE
from ._view_inputs import RATE as RATE
from ._view_inputs import outputs_of, poses_of, script_output, target_of
from ._watch import web_module

EPILOG = """\
The page is served from this computer (no network needed): open the printed URL.
--host 127.0.0.1 (default) lets only this computer see it; 0.0.0.0 serves every network.
Units: target and poses in mm and degrees.

--follow shows the simulated arm that OTHER armkit commands move (each of them
publishes its arm while somebody follows, and runs in real time then).

examples:
  armkit view                                   # the simulated OpenManipulator-X, teach from the page
  armkit --scene board_001 view --target 265 0 20 --pitch -90
  armkit --scene board_001 view --pose 0 20 10 -40 --screenshot view.png
  armkit view --write taught.arm               # 'Record pose' on the page, Ctrl-C writes the script
  armkit --scene board_001 view --follow        # then, in another terminal:
  armkit --scene board_001 stack red green blue
  armkit --arm lynx6 view --gif tour.gif --pose 90 90 90 90 90 --pose 60 110 70 80 90
"""


def add_commands(sub: argparse._SubParsersAction[Any]) -> None:
    """Add ``view``."""
    p = sub.add_parser(
        "view",
        help="a live 3D view of the arm in the browser; teach poses; pictures (web extra)",
        description="Serve a 3D page of the arm on its table: links as the clearance capsules, "
        "the gripper, the tool's trail, a target marker (green: reachable and clear; red: why "
        "not). Joint sliders and a draggable target move the arm; 'Record pose' keeps poses.",
        epilog=EPILOG,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument("--contacts", action="store_true", help="with --physics mujoco and --scene, draw where MuJoCo's bodies touch (orange dots)")  # fmt: skip
    p.add_argument(
        "--host", default="127.0.0.1", metavar="ADDRESS",
        help="address to serve on (default 127.0.0.1)",
    )  # fmt: skip
    p.add_argument(
        "--port",
        dest="http_port",
        type=int,
        default=8080,
        action=_ChosenPort,
        help="TCP port of the page (default 8080, or the next free one; 0 = any free; a "
        "port given here and busy is refused); the driver's port is the global --port "
        "before 'view'",
    )
    p.add_argument("--rate", type=float, metavar="HZ", help="updates per second [Hz] (default 30; 45 with --follow, where another process writes the states: 40 new ones a second reach the page on a quiet machine, fewer under load, see docs/performance.md)")  # fmt: skip
    p.add_argument(
        "--frames", action="store_true", help="draw every joint frame's axes (default: off)"
    )
    p.add_argument(
        "--follow",
        action="store_true",
        help="show the simulated arm as other armkit commands move it (no teaching)",
    )
    p.add_argument(
        "--target", nargs=3, type=float, metavar=("X", "Y", "Z"),
        help="show a target marker at X Y Z [mm], green if the arm reaches it clear, red with "
        "why not (default: none; drag it on the page)",
    )  # fmt: skip
    p.add_argument("--pitch", type=float, metavar="DEG", help="target pitch [deg] (default any)")
    p.add_argument(
        "--pose",
        nargs="+",
        type=float,
        action="append",
        metavar="DEG",
        help="joint angles [deg], one per joint; repeat for a path (moves the arm; default: "
        "the arm stays where it is; --gif: over each cube and home)",
    )
    _picture_options(p)
    p.set_defaults(func=run_view)


class _ChosenPort(argparse.Action):
    """``--port N``: remembers that the user chose the port (a busy one is then refused,
    not swapped for the next free one)."""

    def __call__(self, parser: Any, namespace: Any, values: Any, option: Any = None) -> None:
        setattr(namespace, self.dest, values)
        namespace.port_chosen = True


def _picture_options(p: argparse.ArgumentParser) -> None:
    p.add_argument(
        "--write",
        metavar="FILE.arm",
        help="when the view stops, write the recorded poses and the moves made as a script "
        "'armkit run' replays (joint angles in deg, gripper in mm; default: no file)",
    )
    p.add_argument(
        "--screenshot", metavar="FILE.png",
        help="write a picture of the view and exit (default: serve the page)",
    )  # fmt: skip
    p.add_argument(
        "--size",
        nargs=2,
        type=int,
        default=(1024, 768),
        metavar=("W", "H"),
        help="size of the --screenshot picture [px] (default 1024 768)",
    )
    p.add_argument(
        "--gif",
        metavar="FILE.gif",
        help="write an animation of the --pose path and exit (default: serve the page)",
    )
    p.add_argument(
        "--fps", type=float, default=15.0, metavar="HZ",
        help="--gif frames per second [1/s] (default 15)",
    )  # fmt: skip


def run_view(args: argparse.Namespace) -> int:
    """Check every input and output first, then open the arm and serve or draw."""
    from ..model import load_model
    from ._scene import scene_of

    model = load_model(args.arm)
    poses = poses_of(args.pose, model)
    outputs = outputs_of(args)
    script = script_output(args)
    target = target_of(args)
    scene = scene_of(args, required=False)
    if not args.gif:
        _address(args)
    if args.follow:
        return _follow(args, model, scene, target, outputs)
    if args.gif:
        return _gif(args, model, poses, Path(args.gif), scene)
    web = web_module()
    arm = _open_arm(args, model, scene)
    source = _source(arm, scene, bool(getattr(args, "contacts", False)))
    view = web.View(source, scene=scene, **_view_options(args))
    teach = None
    try:
        teach = web.Teach(view, arm)
        view.start()
        for q in poses:
            teach.move_joints(q)
            teach.mover.wait_idle()
        view.update()
        if target is not None:  # a marker only: the arm stays where it is (--help)
            view.set_target(target[0], target[1])
        done = _finish(args, web, view, outputs, target, teach.close, teach.poses)
        if script is not None:
            _write_script(script, teach)
        return done
    finally:
        if teach is not None:  # its mover's thread ends with the command (a screenshot too)
            teach.close()
        view.close()
        arm.close()


def _address(args: argparse.Namespace) -> None:
    """Check --host and --port before anything opens: the host is an address of this
    computer, the port free (one the user chose: else refused; the default 8080: else the
    next free one, said in a line)."""
    from ..viz import serve_address

    chosen = getattr(args, "port_chosen", False)
    address = serve_address(args.host, args.http_port, exact=chosen)
    if address.note:
        print(f"armkit view: {address.note}", flush=True)
    args.http_port = address.port


def _view_options(args: argparse.Namespace) -> dict[str, Any]:
    return {"host": args.host, "port": args.http_port, "rate_hz": args.rate, "frames": args.frames}


def _source(arm: Any, scene: Any, contacts: bool = False) -> Any:
    """What the view shows: the simulated arm's world (its cubes moved by the scene's
    physics), or the real arm's driver."""
    from ..viz import ArmSource, WorldSource

    if arm.world is None:
        return ArmSource(arm)
    physics = None
    if scene is not None:
        from ..physics import physics_for

        physics = physics_for(scene)  # the rules', or MuJoCo's (--physics, the scene file)
        arm.world.attach(physics)
    return WorldSource(arm.world, arm.world.arm().name, physics, contacts)


def _follow(
    args: argparse.Namespace, model: Any, scene: Any, target: Any, outputs: list[Path]
) -> int:
    """Show the simulated arm other processes move (``armkit.viz.LiveSource``)."""
    if args.driver_name != "sim" or args.port == "emu":
        raise InputError("--follow shows a simulated arm kept by other armkit commands (--driver sim); a real arm: drop --follow")  # fmt: skip
    if args.pose or args.gif:
        raise InputError("--follow only watches: drop --pose and --gif (move the arm from another command)")  # fmt: skip
    from ..connect import sim_state_file
    from ..viz import LiveSource

    web = web_module()
    state = Path(args.port) if args.port else sim_state_file(model)
    source = LiveSource(model, state)
    view = web.View(source, scene=scene, **_view_options(args))
    try:
        view.start()
        view.update()
        return _finish(args, web, view, outputs, target, lambda: None, {})
    finally:
        view.close()
        source.close()


def _finish(
    args: argparse.Namespace,
    web: Any,
    view: Any,
    outputs: list[Path],
    target: Any,
    stop: Any,
    poses: dict[str, Any],
) -> int:
    """Show the target, then write the picture or serve until Ctrl-C."""
    from ..viz import describe_target

    if target is not None:
        check = view.set_target(target[0], target[1]) if args.follow else view.target
        print(f"armkit view: {describe_target(check)}")
    if outputs:
        with Progress("screenshot", len(web.RENDER_STEPS), "steps") as bar:
            path = web.render_png(
                view, outputs[0], *args.size, progress=lambda k, step: bar.update(k, step)
            )
        print(f"armkit view: wrote {path}")
        return 0
    return _serve(view, stop, poses)


def _serve(view: Any, stop: Any, poses: dict[str, Any]) -> int:
    try:  # Ctrl-C as soon as the URL is out still stops cleanly
        print(f"armkit view: {view.url}  (Ctrl-C stops)", flush=True)
        if view.host not in ("127.0.0.1", "localhost", "::1"):
            print(f"armkit view: serving on {view.host}: other computers can open the page")
        while True:
            time.sleep(0.5)
    except KeyboardInterrupt:
        print("\narmkit view: stopped")
    finally:
        stop()
    for pose in poses.values():
        print(f"  {pose.line()}")
    return 0


def _open_arm(args: argparse.Namespace, model: Any, scene: Any) -> Any:
    """The Arm of --arm/--driver/--port; a simulated arm keeps its pose between runs in
    its state file, as for 'move' (``cli._kept.open_kept``)."""
    from ..arm import Arm
    from ._kept import open_kept

    return Arm(model, open_kept(model, args), scene=scene)


def _write_script(path: Path, teach: Any) -> None:
    from .._files import write_atomic

    write_atomic(path, teach.script(), durable=False)
    poses = count(len(teach.poses), "pose")
    print(f"armkit view: wrote {poses} to {path}; replay with: armkit run {path}")


def _gif(args: argparse.Namespace, model: Any, poses: list[Any], path: Path, scene: Any) -> int:
    from ..arm import Arm
    from ..viz import default_tour, record_path, write_gif

    with Arm(model, args.driver_name, args.port, scene=scene) as arm:
        frames = record_path(arm, poses or default_tour(model, scene), args.fps)
    write_gif(model, frames, path, scene=scene, fps=args.fps)
    took = frames[-1].t - frames[0].t
    print(f"armkit view: wrote {path} ({len(frames)} frames, {took:.1f} s of motion)")
    return 0
