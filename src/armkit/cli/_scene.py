"""``armkit scene list`` and ``armkit --scene FILE scene show`` (text and a top view)."""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import TYPE_CHECKING, Any

from .._errors import ArmkitError
from .._terminal import count
from ..scene import shipped_scenes

if TYPE_CHECKING:
    from ..scene import shipped_scenes

SCENE_HELP = "scenes are TOML files in millimetres and degrees (see docs/jobs/tasks.md); shipped: "


def add_commands(sub: argparse._SubParsersAction[Any]) -> None:
    """Add ``scene list`` and ``scene show``."""
    scene = sub.add_parser("scene", help="what is on the table: list shipped scenes, show one")
    verbs = scene.add_subparsers(dest="verb", metavar="VERB", required=True)
    p = verbs.add_parser("list", help="the shipped scenes")
    p.set_defaults(func=_list)
    p = verbs.add_parser(
        "show",
        help="print the scene given with --scene and draw it from above",
        description="Print every object of the scene (mm, deg) and write a top view.",
        epilog=SCENE_HELP + ", ".join(shipped_scenes()),
    )
    p.add_argument(
        "-o",
        "--output",
        metavar="FILE.png",
        help="top view picture (.png, .svg, .pdf; default <scene>_top.png; needs matplotlib)",
    )
    p.add_argument("--no-picture", action="store_true", help="print only, write no picture")
    p.set_defaults(func=_show)
    p = verbs.add_parser(
        "reset",
        help="forget where the simulator keeps a scene's objects (back as the file puts them) "
        "and the simulated arms' kept poses (back at home)",
    )
    p.add_argument("name", metavar="NAME|FILE", help="the scene (shipped name or file)")
    p.set_defaults(func=_reset)


def scene_of(args: argparse.Namespace, required: bool = True) -> Any:
    """The scene named by the global ``--scene`` (None if not given and not required)."""
    from ..scene import load_scene, shipped_scenes

    if args.scene is None:
        if not required:
            return None
        raise ArmkitError(
            f"'{args.command}' needs a scene: give --scene FILE|NAME before the command "
            f"(shipped: {', '.join(shipped_scenes())})"
        )
    scene = load_scene(args.scene)
    physics = getattr(args, "physics", None)
    if physics is None or physics == scene.physics:
        return scene
    from dataclasses import replace

    return replace(scene, physics=physics)  # --physics over the file's 'physics'


def _kept(args: argparse.Namespace, model: Any, scene: Any) -> tuple[Any, str | None]:
    """The scene with its cubes where the simulated arm of --arm/--port keeps them (what
    its next command sees), and the held cube's name; the file's when nothing is kept."""
    from ..scene import load_physics, scene_state_file
    from ..sim import kept_key

    if args.driver_name != "sim" or args.port == "emu":
        return scene, None
    path = scene_state_file(scene, kept_key(model, args.port))
    if not path.exists():
        return scene, None
    physics = load_physics(path, scene)
    print(
        f"as kept for the simulated {model.name} ({path}; 'armkit scene reset {scene.name}' restores the file's)"
    )
    held = physics.holding
    return physics.scene, None if held is None else held.cube.name


def _reset(args: argparse.Namespace) -> int:
    from .._files import config_dir
    from .._lock import held
    from ..scene import load_scene

    scene = load_scene(args.name)
    found = sorted(config_dir().glob(f"scene_{scene.name}-*.json"))
    for path in found:
        with held(path, f"the simulated objects of {scene.name}"):
            path.unlink()
    print(f"{scene.name}: {len(found)} kept state(s) forgotten")
    arms = sorted(config_dir().glob("sim_*.json"))  # the simulated arms' kept poses
    for path in arms:
        with held(path, "a kept simulated arm"):
            path.unlink()
    if arms:
        print(f"simulated arms: {len(arms)} kept pose(s) forgotten (they start at home again)")
    return 0


def _list(args: argparse.Namespace) -> int:
    from ..scene import load_scene, shipped_scenes

    for name in shipped_scenes():
        scene = load_scene(name)
        print(
            f"{name:12s} {count(len(scene.names()), 'object')}: {', '.join(scene.names()) or 'empty table'}"
        )
    return 0


def _show(args: argparse.Namespace) -> int:
    from .._files import check_output_path
    from ..model import load_model
    from ..scene import PICTURE_SUFFIXES, describe, top_view

    scene = scene_of(args)
    model = load_model(args.arm)
    out = None if args.no_picture else Path(args.output or f"{scene.name}_top.png")
    if out is not None:
        check_output_path(out, "-o/--output", PICTURE_SUFFIXES)
    scene, held = _kept(args, model, scene)
    print("\n".join(describe(scene)))
    if held is not None:
        print(f"in the gripper:\n  {held}")
    if out is not None:
        top_view(scene, out, model)
        print(f"top view written to {out}")
    return 0
