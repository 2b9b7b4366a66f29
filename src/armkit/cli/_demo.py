"""``armkit demo``: the showcase, on simulated arms only (no hardware, nothing kept).

1. Every shipped arm, on its own simulated controller under its real driver,
   reaches a point in front of it (inverse kinematics, checked by forward).
2. Every shipped scene: on 001's board the OpenManipulator-X turns the three
   cubes and stacks them (the scene's physics grasps and carries them); on
   002's table it puts the object in the container; other scenes are listed.
3. The OpenManipulator-X draws a 40 mm circle and the pen's true path is measured.

A picture of the stack is written (``-o``); ``--gif`` records the stack, ``--view``
shows it live in the browser in real time. It ends with commands to try next.
"""

from __future__ import annotations

import argparse
import importlib.util
import math
import warnings
from pathlib import Path
from typing import Any

from .._errors import ArmkitError
from .._files import check_output_path
from ._table import table
from ._watch import add_watch_options, watch_world, watching

NEXT = (
    "armkit --scene board_001 rotate-cube red --gif rotate.gif",
    "armkit --scene search_002 move-item object bin",
    "armkit --arm lynx6 ik 200 0 50 --pitch -45 --all",
    "armkit scene list",
)
SCREENSHOT = "armkit --scene board_001 view --screenshot board.png"  # web extra and Chromium
TOUR = "armkit --scene board_001 view --gif tour.gif"  # the picture without a browser (plot)
FOLLOW = "armkit --scene board_001 view --follow"  # the web extra
REACH = (0.55, 0.0, 0.25)  # the point each arm reaches: fractions of its reach (x, y, z)


def add_commands(sub: argparse._SubParsersAction[Any]) -> None:
    """Add ``demo``."""
    p = sub.add_parser(
        "demo",
        help="the showcase: every simulated arm and scene (stack, put away, draw); no hardware",
        description="Every shipped arm reaches a point on its simulated controller; the "
        "OpenManipulator-X stacks 001's cubes, puts 002's object in its container and draws a "
        "circle. Nothing is kept between runs.",
    )
    p.add_argument("-o", "--output", default="demo.png", metavar="FILE.png", help="picture of the stacked cubes (default demo.png)")  # fmt: skip
    add_watch_options(p)
    p.set_defaults(func=run_demo)


def run_demo(args: argparse.Namespace) -> int:
    """Check the outputs, then run the three parts and say what to try next."""
    output = check_output_path(args.output, "-o/--output", (".png",))
    args.arm, args.driver_name, args.port = "openmanipulator_x", "sim", None  # the showcase's own
    world = watch_world(args)
    print("armkit demo: simulated arms, each under its real driver (no hardware)\n")
    _every_arm()
    try:
        _stack(args, world, output)
    finally:
        if world is not None:
            world.close()
    _put_away()
    _other_scenes()
    _draw_circle()
    print("\nNext: " + ", ".join(f"'{command}'" for command in next_commands()) + ".")
    if has_web():
        print(f"Watch them: '{FOLLOW}' in one terminal (open its URL), one of them in another.")
    else:
        print("Watch them in a 3D page in the browser: pip install 'armkit[web]'.")
    return 0


def has_web() -> bool:
    """Whether the web extra (viser) is installed: ``view --follow`` and ``--screenshot``."""
    return importlib.util.find_spec("viser") is not None


def next_commands() -> tuple[str, ...]:
    """The commands the demo suggests, each one that runs here: a screenshot of the 3D
    page where the web extra and Chromium are, else an animation of it (plot extra)."""
    picture = TOUR
    if has_web():
        from ..viz.web import find_chromium

        picture = SCREENSHOT if find_chromium() is not None else TOUR
    return (*NEXT[:1], picture, *NEXT[1:])


def _every_arm() -> None:
    """Each shipped arm reaches a point in front of it; the error by forward kinematics."""
    import numpy as np

    from ..arm import Arm
    from ..drivers.timed import UncertainEstimateWarning
    from ..kinematics import fk
    from ..model import load_model, shipped_models
    from ..viz import reach_of

    rows = []
    for name in shipped_models():
        model = load_model(name)
        r = reach_of(model)
        target = np.array([REACH[0] * r, REACH[1] * r, model.table_z + REACH[2] * r])
        with Arm(model) as arm, warnings.catch_warnings():
            warnings.simplefilter("ignore", UncertainEstimateWarning)  # the OWI: never homed
            start = arm.clock.now()
            x, y, z = (target * 1000).tolist()
            try:
                arm.move_to(x, y, z)
            except ArmkitError as exc:
                rows.append([name, model.dof, f"{x:.0f} {y:.0f} {z:.0f}", f"refused: {exc}", ""])
                continue
            assert arm.world is not None  # simulated: where the arm truly is
            truth = arm.world.arm().q()
            err = float(np.linalg.norm(fk(model, truth)[:3, 3] - target)) * 1000
            took = arm.clock.now() - start
            rows.append([name, model.dof, f"{x:.0f} {y:.0f} {z:.0f}", f"{err:.2f}", f"{took:.2f}"])
    head = ["arm", "joints", "target x y z mm", "off by mm", "took s"]
    print("1. Every arm reaches a point in front of it; off by: where it truly is (simulated)")
    print(table(head, rows))
    print("   (the OWI-535 has no sensors: it moves by timing its motors, from an estimate)")


def _stack(args: argparse.Namespace, world: Any, output: Path) -> None:
    """001: the OpenManipulator-X turns and stacks the three cubes of the board scene."""
    from .. import tasks
    from ..arm import Arm
    from ..connect import open_driver
    from ..model import load_model
    from ..scene import load_scene
    from ..viz import WorldSource, write_picture

    scene = load_scene("board_001")
    model = load_model("openmanipulator_x")
    print("\n2. 001's board: the OpenManipulator-X turns each cube in place, then stacks them")
    with (
        Arm(model, open_driver(model, world=world), scene=scene) as arm,
        watching(args, arm, scene) as physics,
    ):
        plan = tasks.stack(arm, scene, ["red", "green", "blue"], dry_run=True)
        start = arm.clock.now()
        tasks.run_plan(arm, plan)
        took = arm.clock.now() - start
        assert arm.world is not None  # simulated
        state = WorldSource(arm.world, physics=physics).state()
        write_picture(model, state, output, scene=scene, title="armkit demo: 001's cubes stacked")
    tops = ", ".join(f"{o.name} {o.T[2, 3] * 1000:.1f}" for o in state.objects)
    print(f"   {len(plan.steps)} steps in {took:.1f} s; cube centres now at z [mm]: {tops}")
    print(f"   picture of the stack: {output}")


def _put_away() -> None:
    """002: the OpenManipulator-X picks the object up and puts it in the container."""
    from .. import tasks
    from ..arm import Arm
    from ..scene import ScenePhysics, load_scene

    scene = load_scene("search_002")
    print("\n3. 002's table: the OpenManipulator-X puts the object in the container")
    with Arm("openmanipulator_x", scene=scene) as arm:
        assert arm.world is not None  # simulated
        physics = ScenePhysics(scene)
        arm.world.attach(physics)
        plan = tasks.move_item(arm, scene, "object", "bin", dry_run=True)
        tasks.run_plan(arm, plan)
        where = physics.cube("object").position * 1000
    events = "; ".join(e.detail for e in physics.events)
    print(f"   {events}; the object is at ({where[0]:.0f}, {where[1]:.0f}, {where[2]:.0f}) mm")


def _other_scenes() -> None:
    from ..scene import load_scene, shipped_scenes

    for name in shipped_scenes():
        if name not in ("board_001", "search_002"):
            scene = load_scene(name)
            print(f"   scene {name}: {', '.join(scene.names()) or 'nothing on the table'}")


def _draw_circle() -> None:
    """Draw a 40 mm circle with the simulated arm and measure the pen's true path."""
    import numpy as np

    from ..arm import Arm
    from ..kinematics import fk
    from ..model import load_model
    from ..motion import TimedStreaming, circle, distance_to_polyline

    m = load_model("openmanipulator_x")
    print("\n4. The OpenManipulator-X draws a 40 mm circle, pen down (timed streaming, 100 Hz):")
    with Arm(m, driver="sim") as arm:  # in memory: the demo leaves no state behind
        world = arm.world
        assert world is not None  # driver="sim" is simulated
        points = circle(np.array([0.17, 0.0, 0.05]), 0.04, spacing=0.002) * 1000
        x, y, z = points[0]
        arm.move_to(x, y, z, -90.0)
        start = arm.clock.now()
        arm.follow(points, -90.0, streamer=TimedStreaming(rate=100.0, speed=0.06))
        took = arm.clock.now() - start
        record = world.recording().between(start, arm.clock.now())
        error = distance_to_polyline(fk(m, record.q)[:, :3, 3] * 1000, points)
    rms, worst = math.sqrt(float(np.mean(error**2))), float(error.max())
    print(f"   {len(points)} waypoints in {took:.2f} s; the pen's true path is {rms:.3f} mm RMS, {worst:.3f} mm at worst from the circle")  # fmt: skip
