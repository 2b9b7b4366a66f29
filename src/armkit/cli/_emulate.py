"""``armkit emulate``: a simulated controller on a pseudo-terminal, for any program to open."""

from __future__ import annotations

import argparse
import sys
from types import FrameType
from typing import TYPE_CHECKING, Any

from .._errors import InputError
from ..connect import driver_kind, emulate, emulated_kinds, listed

if TYPE_CHECKING:
    import threading

EPILOG = """\
The first line printed is the pseudo-terminal's path (say /dev/pts/7); open it like a
serial port, from armkit itself (--port /dev/pts/7 with --driver {drivers})
or from any program:

  armkit emulate ssc32 --arm lynx6 &
  python -c "import serial; s = serial.Serial('/dev/pts/7', 9600); s.write(b'VER\\r')"

The device runs in real time until Ctrl-C (or SIGTERM). The arm is --arm, given
after 'emulate' or, as for every command, before it (armkit --arm lynx6 emulate ssc32);
without it the device is a lone controller: an SSC-32 at 9600 baud, a Maestro, or the
OpenManipulator-X's five XM430 servos (IDs 11..15) at 1,000,000 baud.
"""


def add_commands(sub: argparse._SubParsersAction[Any]) -> None:
    """Add ``emulate``: one choice per driver kind with an emulator (``emulated_kinds``)."""
    kinds = emulated_kinds()
    p = sub.add_parser(
        "emulate",
        help=f"serve a simulated {listed([kind.title for kind in kinds])} on a pseudo-terminal",
        description="Start a simulated controller on a pseudo-terminal, print its path and "
        "serve until Ctrl-C, so any program or library (pyserial, the dynamixel-sdk, "
        "armkit itself with --port PATH) can talk to it as to the hardware.",
        epilog=EPILOG.format(drivers=listed([kind.name for kind in kinds])),
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument(
        "kind", choices=[kind.name for kind in kinds], help="which controller to emulate"
    )
    p.add_argument(
        "--arm",
        dest="emulate_arm",
        metavar="NAME|FILE",
        help="drive this arm's simulated servos (its channels, IDs, baud rate; default: the "
        "global --arm if given, else none)",
    )
    p.set_defaults(func=run_emulate)


def run_emulate(args: argparse.Namespace) -> int:
    """Serve until interrupted; the path goes to stdout, the rest to stderr."""
    import signal
    import threading

    from ..model import load_model

    arm = _arm(args)
    model = load_model(arm) if arm else None
    emulator = emulate(args.kind, model)
    done = threading.Event()
    previous = signal.signal(signal.SIGTERM, lambda n, f: _stop(done, n, f))
    try:
        what = driver_kind(args.kind).device + (f" driving the {model.name}" if model else "")
        try:
            print(emulator.port, flush=True)
            print(f"armkit: {what} on {emulator.port}; Ctrl-C to stop", file=sys.stderr, flush=True)
            while not done.wait(0.5):
                pass
        except KeyboardInterrupt:
            pass  # Ctrl-C is how an emulator ends
        print(f"armkit: emulator stopped; {emulator.reply_summary()}", file=sys.stderr)
    finally:
        signal.signal(signal.SIGTERM, previous)
        emulator.close()
    return 0


def _arm(args: argparse.Namespace) -> str | None:
    """The arm to drive: --arm after 'emulate', or the global --arm if it was given (not
    its default); both and different: InputError."""
    own = args.emulate_arm
    before = args.arm if "arm" in getattr(args, "given", ()) else None
    if own and before and own != before:
        raise InputError(
            f"two arms: --arm {before} before 'emulate' and --arm {own} after it; give one"
        )
    return own or before


def _stop(done: threading.Event, signum: int, frame: FrameType | None) -> None:
    done.set()
