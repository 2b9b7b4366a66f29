"""The inputs of ``armkit view``, every one checked before the arm is opened or a
file written: poses [deg], the target [mm], the rate [Hz], the page's port, picture
size [px] and frame rate, and each output file (suffix, folder, writable)."""

from __future__ import annotations

import argparse
import math
from pathlib import Path
from typing import Any

from .._errors import InputError
from .._files import check_output_path

RATE = 30.0  # [Hz] updates of the view
FOLLOW_RATE = 45.0  # [Hz] with --follow: ~40 new states a second from the 100 Hz live file


def poses_of(given: list[list[float]] | None, model: Any) -> list[Any]:
    """Each ``--pose`` [deg] as joint angles [rad], shape (dof,), within the joint limits."""
    import numpy as np

    poses = []
    for angles in given or []:
        if len(angles) != model.dof or not all(math.isfinite(a) for a in angles):
            names = ", ".join(model.joint_names)
            raise InputError(f"--pose needs {model.dof} angles in degrees ({names}), got {angles}")
        q = np.radians(angles)
        if not model.within_limits(q):
            raise InputError(
                f"--pose {angles} deg is outside {model.name}'s joint limits; see 'armkit show'"
            )
        poses.append(q)
    return poses


def target_of(args: argparse.Namespace) -> tuple[Any, float | None] | None:
    """``--target`` [mm] as (point [m], shape (3,), ``--pitch`` [deg] or None); None if not given."""
    import numpy as np

    if args.target is None:
        if args.pitch is not None:
            raise InputError("--pitch needs --target X Y Z [mm]")
        return None
    if not all(math.isfinite(v) for v in args.target):
        raise InputError(f"--target must be 3 finite numbers [mm], got {args.target}")
    return np.array(args.target) / 1000.0, args.pitch


def outputs_of(args: argparse.Namespace) -> list[Path]:
    """Every output file checked before anything moves: suffix, folder, writable."""
    if args.rate is None:
        args.rate = FOLLOW_RATE if args.follow else RATE
    if not 1 <= args.rate <= 240:
        raise InputError(f"--rate must be 1..240 Hz, got {args.rate}")
    if not 0 <= args.http_port <= 65535:
        raise InputError(f"--port must be 0..65535, got {args.http_port}")
    if args.gif and args.driver_name != "sim" and args.port != "emu":
        raise InputError("--gif animates a simulated arm; drop --driver (or use --port emu)")
    if args.screenshot and args.gif:
        raise InputError("give --screenshot or --gif, not both")
    w, h = args.size
    if not (64 <= w <= 4096 and 64 <= h <= 4096):
        raise InputError(f"--size must be 64..4096 px each, got {w} {h}")
    if not 1 <= args.fps <= 60:
        raise InputError(f"--fps must be 1..60, got {args.fps}")
    out = []
    for given, suffix, flag in (
        (args.screenshot, ".png", "--screenshot"),
        (args.gif, ".gif", "--gif"),
    ):
        if given:
            out.append(check_output_path(given, flag, (suffix,)))
    return out


def script_output(args: argparse.Namespace) -> Path | None:
    """The --write file, checked before anything starts (None: not asked)."""
    if not args.write:
        return None
    if args.follow or args.gif:
        raise InputError("--write keeps what is taught on the page; drop --follow and --gif")
    return check_output_path(args.write, "--write", (".arm",))
