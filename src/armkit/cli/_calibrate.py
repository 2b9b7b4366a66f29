"""``armkit calibrate``: measure this unit and save it (OWI timings, Lynx6 pulse tables)."""

from __future__ import annotations

import argparse
import importlib
from typing import Any

from .._closing import closing
from .._errors import ArmkitError, InputError
from .._files import config_dir
from ..connect import auto_operator
from ..model import load_model
from ._args import check_folder
from ._kept import open_kept

# driver name -> the module whose run_calibration(model, driver, ask, say) measures it
CALIBRATORS = {
    "owi535": "armkit.drivers.timed",
    "ssc32": "armkit.drivers.servo",
    "maestro": "armkit.drivers.servo",
}


def add_commands(sub: argparse._SubParsersAction[Any]) -> None:
    """Add ``calibrate``."""
    p = sub.add_parser(
        "calibrate",
        help="measure this unit and save it (OWI: joint timings; Lynx6: servo pulse tables)",
        description="Guide a person through measuring this arm unit, then write its calibration "
        "file (atomically) to the config directory ($ARMKIT_CONFIG_DIR, else ~/.config/armkit). "
        "OWI-535 (--driver owi535, or sim): each joint is timed limit to limit, up and down. "
        "Lynx6 (--driver ssc32 or maestro): each servo visits its table points (ends and every "
        "30 deg) and you type the angle you measure.",
    )
    p.set_defaults(func=run_calibrate)


def _module_for(model_name: str, driver: str) -> str:
    if driver == "sim" and model_name == "owi535":
        return CALIBRATORS["owi535"]
    if driver not in CALIBRATORS:
        raise InputError(
            f"calibrate works with --driver {', '.join(CALIBRATORS)} (or sim on the owi535), got {driver!r}"
        )
    return CALIBRATORS[driver]


def _ask(prompt: str) -> str:
    try:
        return input(prompt + " ")
    except EOFError:
        raise ArmkitError("calibration needs a person at the keyboard, but input ended") from None


def run_calibrate(args: argparse.Namespace) -> int:
    model = load_model(args.arm)
    check_folder(config_dir(), "the config directory")  # where the calibration goes
    module = importlib.import_module(_module_for(model.name, args.driver))
    driver = open_kept(model, args)
    ask = _ask
    if args.driver == "sim":  # the simulated OWI is timed by an automatic operator
        operator = auto_operator(driver)
        ask = operator.ask if operator is not None else _ask
    with closing(driver):
        path = module.run_calibration(model, driver, ask, print)
    print(f"wrote {path}")
    return 0
