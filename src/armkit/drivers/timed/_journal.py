"""The unit's journal: its state file written before and after every motor run,
so that whatever happens (an exception, a signal at any instant, the watchdog,
``kill -9``) the file tells the truth about where the arm is."""

from __future__ import annotations

import warnings
from collections.abc import Callable
from pathlib import Path

from ..._clock import Clock
from ..._errors import ArmkitWarning, DeviceError
from ._motors import Motors, Run
from ._safety import SignalGate
from ._state import UnitState, save

Until = tuple[Callable[[], object], float]  # (wait, watchdog timeout [s])


class UncertainEstimateWarning(ArmkitWarning):
    """A move starts from joint angles that are only an uncertain estimate."""


def write(path: Path, state: UnitState, durable: bool) -> None:
    """Save ``state`` atomically; DeviceError (naming the file) if it cannot be written."""
    try:
        save(state, path, durable)
    except OSError as exc:
        raise DeviceError(
            f"cannot write the OWI state file {path}: {exc.strerror}; "
            "set ARMKIT_CONFIG_DIR to a writable directory"
        ) from None


def journaled_run(
    motors: Motors,
    clock: Clock,
    run: Run,
    save_state: Callable[[UnitState], None],
    pending: UnitState,
    done: Callable[[], UnitState],
    until: Until | None = None,
) -> None:
    """Save ``pending``, run the motors (``until``: a run that ends when ``wait()``
    returns, or at the watchdog's timeout), save ``done()``. A signal at any instant
    leaves the file right: it can only cut short the waits, and it is delivered once
    the final state is saved (SignalGate); a signal before the first motor command
    means no motor starts."""
    with SignalGate() as gate:
        save_state(pending)
        try:
            gate.check()
            if until is None:
                motors.execute(run, lambda s: gate.pause(clock.sleep, s))
            else:
                motors.run_until(run, until[0], until[1], gate.wait)
        finally:
            save_state(done())


def raise_if_watchdog(run: Run) -> None:
    """DeviceError after a run the watchdog had to stop (the state is already saved)."""
    if run.watchdog_fired:
        raise DeviceError(
            "the watchdog stopped the arm: the program did not stop the motors in time; "
            "the angles are estimated from the moment it stopped and are uncertain: "
            "re-home the arm"
        )


def warn(message: str) -> None:
    """The default way to warn before moving from an uncertain estimate."""
    warnings.warn(message, UncertainEstimateWarning, stacklevel=5)
