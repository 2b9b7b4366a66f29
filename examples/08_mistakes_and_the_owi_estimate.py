"""Mistakes are refused before anything moves, and the OWI-535 says how sure it is.

Part 1: wrong values given to ``Arm`` raise ``armkit.InputError`` (an
``ArmkitError`` and a ``ValueError``) naming the argument; the arm stays put.
Part 2: the simulated OWI-535 (timed motors, no sensors) keeps an estimate of
its angles; ``uncertainty`` says why it may be wrong, a short turn is made in
two timed legs, and a second user of the same unit is refused.

Run: .venv/bin/python examples/08_mistakes_and_the_owi_estimate.py
"""

from __future__ import annotations

import warnings

from armkit import Arm, ArmkitError, DeviceError, InputError
from armkit.drivers.timed import UncertainEstimateWarning


def refusals() -> None:
    with Arm("openmanipulator_x", driver="sim") as arm:
        before = arm.angles()
        for what, attempt in [
            ("a 100 s move", lambda: arm.move_joints([10, -60, 20, 40], duration=100)),
            ("NaN for an angle", lambda: arm.move_joints([float("nan"), 0, 0, 0])),
            ("a word for x", lambda: arm.move_to("far", 0, 50)),
            ("too wide a grip", lambda: arm.grip(500)),
        ]:
            try:
                attempt()
            except InputError as exc:
                print(f"{what:17s} -> refused: {exc}")
        assert arm.angles() == before
        print("the arm did not move\n")


def owi_estimate() -> None:
    with Arm("owi535", driver="sim") as arm:
        driver = arm.driver
        print(f"OWI-535 estimate uncertain: {driver.uncertainty}")  # type: ignore[attr-defined]
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always", UncertainEstimateWarning)
            arm.move_joints([3, 0, 0, 0])  # under the 200 ms minimum run: two timed legs
        print(f"warned before moving: {caught[0].message}")
        print(f"base now {arm.angles()['base']:.2f} deg (asked 3.00)")
        try:
            Arm("owi535", driver="sim")  # the same simulated unit, a second time
        except DeviceError as exc:
            print(f"a second user: {exc}")


if __name__ == "__main__":
    try:
        refusals()
        owi_estimate()
    except ArmkitError as exc:
        raise SystemExit(f"example failed: {exc}") from None
