"""The arm a motion command (and ``armkit run``) moves: opened once every file it will
write is known to be writable, with the OWI's uncertain-estimate warning as one CLI
line, and watched as ``--view``/``--gif`` say (``armkit.cli._watch``); with ``--scene``
its moves are checked against the scene's objects (where a simulated arm has them)."""

from __future__ import annotations

import argparse
import contextlib
import sys
from collections.abc import Iterator
from typing import TYPE_CHECKING, Any

from .._files import check_output_path, config_dir
from ..connect import check_sim_port
from ._args import check_folder
from ._kept import open_kept
from ._watch import kept_objects, watch_world, watching

if TYPE_CHECKING:
    from ..arm import Arm


@contextlib.contextmanager
def open_arm(args: argparse.Namespace) -> Iterator[Arm]:
    """The arm of --arm on --driver/--port, once every file it will write is known
    to be writable (the config directory, a state file given as --port, a --gif);
    watched as --view/--gif say (``armkit.cli._watch``)."""
    from ..arm import Arm
    from ..model import load_model

    model = load_model(args.arm)
    check_folder(config_dir(), "the config directory")
    if args.driver_name == "sim" and args.port not in (None, "emu"):
        check_sim_port(model, args.port)
        check_output_path(args.port, "--port (the simulated arm's state file)")
    world = watch_world(args)
    scene = _scene(args)
    try:
        arm = Arm(model, open_kept(model, args, world), scene=scene)
        rehome = f"armkit --arm {args.arm} --driver {args.driver_name} rehome"
        arm.on_uncertain(lambda text: print(f"armkit: warning: {text}: {rehome}", file=sys.stderr))
        with arm, kept_objects(args, arm, scene), watching(args, arm, scene) as physics:
            if physics is not None:  # moves are checked against the objects where they are
                from ..tasks import held_now

                arm.scene, arm.held = physics.scene, held_now(arm)
            yield arm
    finally:
        if world is not None:
            world.close()


def _scene(args: argparse.Namespace) -> Any:
    """The --scene (None if not given): every move is checked against its objects, which
    a simulated arm keeps between commands (``--port FILE``) and shows when watched."""
    from ._scene import scene_of

    return scene_of(args, required=False)
