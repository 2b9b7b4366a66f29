"""How far the OWI-535's estimated gripper position drifts from the truth.

On the simulated arm (gravity, gear slip and coast, a draining battery, seeded
randomness), each unit is calibrated by the routine a user runs
(``calibrate_owi535`` with an automatic operator), its estimate is set to the
truth, and it makes 20 random reachable moves (gripper level, above the
table). After each move the estimated gripper position (forward kinematics of
the driver's angles) is compared with the true one, for

* 000's model: one constant rate per joint, limit span / the unit's measured
  mean limit-to-limit time (what seed 000 does), and
* armkit's calibrated model: up/down rates, slip + coast, battery.

Both run the same driver code on identical simulated units. Run:
``.venv/bin/python benchmarks/owi_drift.py [--seeds 5] [--moves 20]``.
"""

from __future__ import annotations

import argparse
import os
import tempfile
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from armkit.devices.owi535 import open_device
from armkit.drivers.timed import TimedDriver, calibrate_owi535, constant_rate, state_path
from armkit.drivers.timed._order import lowest_point
from armkit.kinematics import fk
from armkit.model import ArmModel, load_model
from armkit.sim.owi_operator import SimOperator
from armkit.sim.owi_sim import build_sim

F64 = NDArray[np.float64]


def random_targets(model: ArmModel, seed: int, n: int) -> list[F64]:
    """``n`` reachable poses [rad]: gripper level, every point 20 mm above the table."""
    rng = np.random.default_rng(seed)
    lengths = (model.dh[2].a, model.dh[3].a, model.tool_length)
    out: list[F64] = []
    while len(out) < n:
        b, s, e = np.radians([rng.uniform(-90, 90), rng.uniform(-10, 60), rng.uniform(20, 110)])
        q = np.array([b, s, e, np.pi / 2 - s - e])
        if model.within_limits(q) and lowest_point(q, lengths, model.dh[0].d) > 0.02:
            out.append(q)
    return out


def drift(model: ArmModel, seed: int, targets: list[F64], kind: str, workdir: Path) -> list[float]:
    """Gripper position error [m] after each move, for ``kind`` "000" or "armkit"."""
    sim = build_sim(model, seed)
    path = workdir / f"{kind}-{seed}.json"
    driver = TimedDriver(model, open_device(sim.backend), sim.clock, path, durable=False)
    operator = SimOperator(sim, seed)
    calibrate_owi535(model, driver, operator.ask, operator.say)
    state = driver.state
    if kind == "000":
        state = state.with_(timing=constant_rate(model, state.extra["traverse_s"]))
    driver.set_state(state.with_(angles=tuple(float(a) for a in sim.physics.true_q())))
    errors = []
    for q in targets:
        driver.move(q)
        estimate = fk(model, driver.read())[:3, 3]
        truth = fk(model, sim.physics.true_q())[:3, 3]
        errors.append(float(np.linalg.norm(estimate - truth)))
    driver.close()
    return errors


def main() -> None:
    print(f"load average {' '.join(f'{v:.2f}' for v in os.getloadavg())} ({os.cpu_count()} cores)")
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seeds", type=int, default=5, help="simulated units (default 5)")
    parser.add_argument("--moves", type=int, default=20, help="moves per unit (default 20)")
    args = parser.parse_args()
    model = load_model("owi535")
    with tempfile.TemporaryDirectory() as tmp:
        os.environ["ARMKIT_CONFIG_DIR"] = tmp
        results = {
            seed: {
                kind: drift(
                    model, seed, random_targets(model, 1000 + seed, args.moves), kind, Path(tmp)
                )
                for kind in ("000", "armkit")
            }
            for seed in range(args.seeds)
        }
    print_tables(results, args.moves)
    _ = state_path  # the same state files a user gets, in a temporary directory


def print_tables(results: dict[int, dict[str, list[float]]], moves: int) -> None:
    """Per-move errors (mean over units) and the final error of each unit [mm]."""
    print(f"gripper position error [mm], estimated vs true, mean of {len(results)} simulated units")
    print(f"{'move':>4} | {'000 constant rate':>17} | {'armkit calibrated':>17}")
    for k in range(moves):
        e000 = np.mean([r["000"][k] for r in results.values()]) * 1000
        eark = np.mean([r["armkit"][k] for r in results.values()]) * 1000
        print(f"{k + 1:>4} | {e000:17.1f} | {eark:17.1f}")
    print()
    print(
        f"{'unit':>4} | {'000 after ' + str(moves):>17} | {'armkit after ' + str(moves):>17} | ratio"
    )
    for seed, r in results.items():
        a, b = r["000"][-1] * 1000, r["armkit"][-1] * 1000
        print(f"{seed:>4} | {a:17.1f} | {b:17.1f} | {b / a:5.2f}")
    a = float(np.mean([r["000"][-1] for r in results.values()])) * 1000
    b = float(np.mean([r["armkit"][-1] for r in results.values()])) * 1000
    verdict = "met" if b <= a / 3 else "NOT met"
    print(f"mean | {a:17.1f} | {b:17.1f} | {b / a:5.2f}  (target <= 0.33: {verdict})")


if __name__ == "__main__":
    main()
