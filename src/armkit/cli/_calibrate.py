"""``armkit calibrate``: measure this unit and save it (OWI timings, Lynx6 pulse tables,
an SO-101's LeRobot calibration file)."""

from __future__ import annotations

import argparse
from typing import TYPE_CHECKING, Any

from .._closing import closing
from .._errors import ArmkitError, InputError
from .._files import config_dir
from ..connect import Ask, CalibrationRoutine, driver_kinds, native_kind
from ._args import check_folder
from ._kept import open_kept

if TYPE_CHECKING:
    from ..model import ArmModel


def add_commands(sub: argparse._SubParsersAction[Any]) -> None:
    """Add ``calibrate``."""
    p = sub.add_parser(
        "calibrate",
        help="measure this unit and save it (OWI: joint timings; Lynx6: servo pulse tables; "
        "SO-101: LeRobot's calibration file)",
        description="Guide a person through measuring this arm unit, then write its calibration "
        "file (atomically) to the config directory ($ARMKIT_CONFIG_DIR, else ~/.config/armkit). "
        "OWI-535 (--driver owi535, or sim): each joint is timed limit to limit, up and down. "
        "Lynx6 (--driver ssc32 or maestro): each servo visits its table points (ends and every "
        "30 deg) and you type the angle you measure. SO-101/SO-100 (--driver feetech, or sim): "
        "LeRobot's procedure (the middle of the range is the half turn, each joint to both "
        "ends) written to the servos and to <arm>_feetech.json in LeRobot's format.",
    )
    p.set_defaults(func=run_calibrate)


def _calibration(model: ArmModel, driver: str) -> CalibrationRoutine:
    """How ``driver`` calibrates ``model``: its kind's, or on the simulator (``sim``) the
    native kind's where an automatic operator answers for the person."""
    name = native_kind(model) if driver == "sim" else driver
    found = next((kind.calibrate for kind in driver_kinds() if kind.name == name), None)
    if found is not None and (driver != "sim" or found.operator is not None):
        return found
    kinds = {kind.name: kind.calibrate for kind in driver_kinds() if kind.calibrate is not None}
    on_sim = " or ".join(name for name, how in kinds.items() if how.operator is not None)
    raise InputError(
        f"calibrate works with --driver {', '.join(kinds)} (or sim on the {on_sim}), got {driver!r}"
    )


def _ask(prompt: str) -> str:
    try:
        return input(prompt + " ")
    except EOFError:
        raise ArmkitError("calibration needs a person at the keyboard, but input ended") from None


def run_calibrate(args: argparse.Namespace) -> int:
    from ..model import load_model

    model = load_model(args.arm)
    check_folder(config_dir(), "the config directory")  # where the calibration goes
    calibration = _calibration(model, args.driver_name)
    driver = open_kept(model, args)
    ask: Ask = _ask
    if args.driver_name == "sim" and calibration.operator is not None:  # an automatic operator
        ask = calibration.operator(driver) or _ask
    with closing(driver):
        path = calibration.run(model, driver, ask, print)
    print(f"wrote {path}")
    return 0
