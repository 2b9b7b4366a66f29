"""``armkit urdf -o FILE`` and ``armkit mjcf [-o FILE]``: the arm (and with --scene its
table and objects) as a URDF or MuJoCo MJCF file (``armkit.interchange``)."""

from __future__ import annotations

import argparse
from typing import Any

from .._files import check_output_path, write_atomic


def add_commands(sub: argparse._SubParsersAction[Any]) -> None:
    """Add ``urdf`` and ``mjcf``."""
    p = sub.add_parser(
        "urdf",
        help="write the arm as a URDF file (links as the clearance capsules, with masses)",
        description="Write the arm (--arm) as URDF: revolute joints with their limits [rad] and "
        "speeds [rad/s], lengths in metres (URDF's units), the tool point as the link 'tool', "
        "each link's capsule (radius from the model's [links] radius_mm) as its geometry and "
        "its mass and inertia from the capsules at 1200 kg/m^3, so MuJoCo, pybullet and "
        "yourdfpy load it as it is.",
    )
    p.add_argument("-o", "--output", required=True, metavar="FILE", help="the .urdf file to write")
    p.set_defaults(func=run_urdf)
    p = sub.add_parser(
        "mjcf",
        help="write the arm (and the --scene) as a MuJoCo MJCF model",
        description="Write the arm (--arm) as a MuJoCo MJCF model: the URDF's bodies, a hinge "
        "joint with limits and a position actuator per joint, the gripper's jaws on slide "
        "joints (actuator 'gripper'), a site 'tool' at the tool point and a keyframe 'home'; "
        "with --scene (before the command) the table, boards, containers and cubes (free "
        "bodies with their mass). Metres and radians (MuJoCo's units).",
    )
    p.add_argument(
        "-o", "--output", metavar="FILE", help="the .xml file to write (default: print it)"
    )
    p.set_defaults(func=run_mjcf)


def run_urdf(args: argparse.Namespace) -> int:
    """Check the output path, then write the file."""
    from ..interchange import urdf_of
    from ..model import load_model

    path = check_output_path(args.output, "-o/--output")
    model = load_model(args.arm)
    write_atomic(path, urdf_of(model))
    print(f"wrote {path} ({model.dof} joints, {len(model.link_radii)} link capsules)")
    return 0


def run_mjcf(args: argparse.Namespace) -> int:
    """Check the output path (if any), load the arm and scene, then write or print."""
    from ..interchange import mjcf_of
    from ..model import load_model
    from ._scene import scene_of

    path = None if args.output is None else check_output_path(args.output, "-o/--output")
    model = load_model(args.arm)
    scene = scene_of(args, required=False)
    text = mjcf_of(model, scene)
    if path is None:
        print(text, end="")
        return 0
    write_atomic(path, text)
    where = f" on scene {scene.name}" if scene is not None else ""
    print(
        f"wrote {path} ({model.dof} joints, gripper: {'yes' if model.gripper.present else 'no'}{where})"
    )
    return 0
