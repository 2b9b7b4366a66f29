"""Servo-controller commands: a raw pulse for testing, and the active pulse tables."""

from __future__ import annotations

import argparse
from typing import Any

from .._errors import DeviceError, InputError
from ..connect import kinds_with
from ._args import integer, number

SERVO_EPILOG = """\
examples:
  armkit --driver ssc32 --port emu servo 0 1500
  armkit --driver maestro --port emu servo 2 1200 --time-ms 500
(emu = the controller's emulator; your controller is --port /dev/ttyUSB0 or similar)
"""

TABLE_EPILOG = """\
examples:
  armkit --arm lynx6 --driver ssc32 servo-table
"""


def add_commands(sub: argparse._SubParsersAction[Any]) -> None:
    """Add ``servo`` (one raw pulse) and ``servo-table`` (the tables in use)."""
    p = sub.add_parser(
        "servo",
        help="send one servo a raw pulse [µs] (ssc32/maestro; for testing the wiring)",
        epilog=SERVO_EPILOG,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument(
        "channel",
        type=integer("", 0, 31),
        help="controller channel (SSC-32: 0..31, Maestro: 0..23)",
    )
    p.add_argument(
        "pulse",
        type=number("µs", 500.0, 2500.0),
        help="pulse width [µs], 500..2500 (1500 = centre)",
    )
    p.add_argument(
        "--time-ms",
        type=integer("ms", 0, 65535),
        default=None,
        help="time for the move [ms], 0..65535 (default: none, the servo moves at once)",
    )
    p.set_defaults(func=run_servo)
    t = sub.add_parser(
        "servo-table",
        help="print each servo's pulse table for --arm on --driver (ssc32/maestro)",
        epilog=TABLE_EPILOG,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    t.set_defaults(func=run_table)


def _servo_driver(args: argparse.Namespace) -> str:
    """The --driver, a kind of hobby-servo controller (InputError otherwise)."""
    hobby = [kind.name for kind in kinds_with("hobby")]
    if args.driver_name not in hobby:
        needs = " or ".join(f"--driver {name}" for name in hobby)
        raise InputError(f"this command needs {needs}, not {args.driver_name!r}")
    return str(args.driver_name)


def run_servo(args: argparse.Namespace) -> int:
    """Check the pulse, send it, wait, print what the controller reports back (the kind's
    own controller: its ``pulses`` part in the registry of driver kinds)."""
    from ..connect import driver_kind, simulated_line

    name = _servo_driver(args)
    pulses = driver_kind(name).pulses
    if pulses is None:
        raise InputError(f"--driver {name} takes no raw pulses")
    if not args.port:
        raise DeviceError("servo needs --port (your controller's serial device, or emu)")
    line, clock = simulated_line(name) if args.port == "emu" else (args.port, None)
    try:
        bus = pulses(line, clock, args.channel, args.pulse)
    except BaseException:
        if args.port == "emu":
            line.close()
        raise
    try:
        bus.move({args.channel: args.pulse}, args.time_ms)
        bus.wait((args.time_ms or 0) / 1000.0 + 2.0)
        back = bus.read([args.channel])[args.channel]
    finally:
        bus.close()
    print(f"channel {args.channel}: sent {args.pulse:g} µs, controller reports {back:g} µs")
    return 0


def run_table(args: argparse.Namespace) -> int:
    """Print every servo's table: point (degrees or mm) -> pulse [µs]."""
    from ..drivers.servo import load_setup
    from ..model import load_model

    driver = _servo_driver(args)
    model = load_model(args.arm)
    setup = load_setup(model, driver)
    source = setup.unit_file if setup.unit_file.is_file() else "ideal (no unit file)"
    print(f"{model.name} on {driver}: tables from {source}")
    for table in (*setup.joints, *([setup.grip] if setup.grip else [])):
        unit = "deg" if table.unit == "deg" else "mm"
        points = "  ".join(
            f"{table.shown(v):.1f}->{p:.0f}"
            for v, p in zip(table.values, table.pulses_us, strict=True)
        )
        print(f"  {table.name:<9} ch {table.channel:>2}  [{unit} -> µs]  {points}")
    return 0
