"""``armkit dxl-scan``: which Dynamixel servos answer on a port, and how they are."""

from __future__ import annotations

import argparse
import contextlib
from typing import TYPE_CHECKING, Any

from .._errors import DeviceError, InputError
from ._args import integer
from ._table import table

if TYPE_CHECKING:
    from ..devices.dynamixel import DynamixelBus

MODE_NAMES = {0: "current", 1: "velocity", 3: "position", 4: "extended", 5: "current-position"}


def add_commands(sub: argparse._SubParsersAction[Any]) -> None:
    """Add ``dxl-scan``."""
    p = sub.add_parser(
        "dxl-scan",
        help="list the Dynamixel servos answering on --port",
        description="Ping IDs on --port (a serial device, or 'emu' for the emulator) and show"
        " each servo's model, mode, torque, hardware error and position (ticks and degrees).",
    )
    p.add_argument(
        "--baud",
        type=integer("bits/s", 9600, 4_500_000),
        default=1_000_000,
        help="bits/s, 9600..4500000 (default 1000000)",
    )
    p.add_argument("--ids", default="0-252", metavar="A-B", help="ID range to ping (default 0-252)")
    p.set_defaults(func=run_scan)


def parse_ids(text: str) -> range:
    """``"11-15"`` -> range(11, 16); ValueError for anything else outside 0..252."""
    low, _, high = text.partition("-")
    try:
        first, last = int(low), int(high or low)
    except ValueError:
        raise InputError(f"--ids must look like 11-15 or 7, got {text!r}") from None
    if not 0 <= first <= last <= 252:
        raise InputError(f"--ids must be inside 0-252, got {text!r}")
    return range(first, last + 1)


def run_scan(args: argparse.Namespace) -> int:
    from ..devices.dynamixel import DynamixelBus

    ids = parse_ids(args.ids)
    if not args.port:
        raise InputError("dxl-scan needs --port: a serial device (/dev/ttyUSB0) or 'emu'")
    with contextlib.ExitStack() as stack:
        if args.port == "emu":
            from ..connect import simulated_bus

            bus = stack.enter_context(simulated_bus(args.baud, retries=0))
        else:
            bus = stack.enter_context(DynamixelBus(args.port, args.baud, retries=0))
        rows = [_row(bus, sid, model) for sid, model in bus.scan(ids).items()]
    if not rows:
        raise DeviceError(
            f"no servo answered on {args.port} at {args.baud} baud (IDs {args.ids});"
            " check power, cable and baud (a new XM430 is ID 1 at 57600)"
        )
    print(table(["id", "model", "name", "mode", "torque", "hw error", "tick", "deg"], rows))
    return 0


def _row(bus: DynamixelBus, sid: int, model: int) -> list[object]:
    from ..devices import xm430 as xm

    if model != xm.MODEL_NUMBER:
        return [sid, model, "?", "", "", "", "", ""]
    errors = bus.hardware_error(sid)
    tick = bus.read(sid, "Present Position", alert_ok=True)
    return [
        sid,
        model,
        "XM430-W350",
        MODE_NAMES.get(bus.read(sid, "Operating Mode", alert_ok=True), "?"),
        "on" if bus.read(sid, "Torque Enable", alert_ok=True) else "off",
        xm.describe_hardware_error(errors) if errors else "-",
        tick,
        round((tick - 2048) * 360.0 / xm.TICKS_PER_TURN, 2),
    ]
